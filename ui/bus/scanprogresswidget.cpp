#include "ui/bus/scanprogresswidget.h"

#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>

namespace dd {

ScanProgressWidget::ScanProgressWidget(QWidget *parent)
    : QWidget(parent)
{
    setObjectName(QStringLiteral("scanProgress"));
    m_stage = new QLabel(this);
    m_stage->setWordWrap(true);
    m_bar = new QProgressBar(this);
    m_bar->setTextVisible(true);
    m_eta = new QLabel(this);
    m_cancel = new QPushButton(this);
    m_cancel->setObjectName(QStringLiteral("cancelScan"));
    auto *layout = new QGridLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_stage, 0, 0, 1, 2);
    layout->addWidget(m_bar, 1, 0, 1, 2);
    layout->addWidget(m_eta, 2, 0);
    layout->addWidget(m_cancel, 2, 1);
    connect(m_cancel, &QPushButton::clicked, this, &ScanProgressWidget::cancelRequested);
    m_cancel->setText(tr("Cancel"));
    hide();
}

void ScanProgressWidget::begin(const QString &what)
{
    m_found = 0;
    setStage(what);
    m_cancel->setEnabled(true);
    show();
}

void ScanProgressWidget::setStage(const QString &what)
{
    m_stage->setText(what);
    m_bar->setRange(0, 0); // busy until the first progress report
    m_estimator.start();
    updateEta();
}

void ScanProgressWidget::setProgress(int done, int total)
{
    if (total <= 0)
        return;
    m_bar->setRange(0, total);
    m_bar->setValue(qBound(0, done, total));
    m_estimator.update(done, total);
    updateEta();
}

void ScanProgressWidget::setFound(int count)
{
    m_found = count;
    updateEta();
}

void ScanProgressWidget::finish()
{
    hide();
}

QString ScanProgressWidget::stageText() const
{
    return m_stage->text();
}

QString ScanProgressWidget::etaText() const
{
    return m_eta->text();
}

void ScanProgressWidget::updateEta()
{
    const QString eta = EtaEstimator::format(m_estimator.remainingMs());
    const QString found = tr("%n drive(s) found", nullptr, m_found);
    m_eta->setText(eta.isEmpty() ? found : tr("%1 left · %2").arg(eta, found));
}

void ScanProgressWidget::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        m_cancel->setText(tr("Cancel"));
        updateEta();
    }
    QWidget::changeEvent(event);
}

} // namespace dd
