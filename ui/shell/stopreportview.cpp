#include "ui/shell/stopreportview.h"

#include "ui/shell/stopreporter.h"

#include <QDialogButtonBox>
#include <QEvent>
#include <QLabel>
#include <QVBoxLayout>

namespace dd {

StopReportView::StopReportView(StopReporter *reporter, QWidget *parent)
    : QDialog(parent)
    , m_reporter(reporter)
{
    setObjectName(QStringLiteral("stopReportView"));
    m_text = new QLabel(this);
    m_text->setObjectName(QStringLiteral("stopReportText"));
    m_text->setWordWrap(true);
    m_text->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_text->setMinimumWidth(480);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_text, 1);
    layout->addWidget(buttons);
    connect(m_reporter, &StopReporter::updated, this, &StopReportView::refresh);
    connect(m_reporter, &StopReporter::finished, this, &StopReportView::refresh);
    refresh();
}

QString StopReportView::text() const
{
    return m_text->text();
}

void StopReportView::refresh()
{
    setWindowTitle(tr("STOP report"));
    m_text->setText(m_reporter->details());
    adjustSize();
}

void StopReportView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        refresh();
    QDialog::changeEvent(event);
}

} // namespace dd
