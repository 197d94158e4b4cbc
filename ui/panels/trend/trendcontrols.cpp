#include "ui/panels/trend/trendcontrols.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QSignalBlocker>
#include <QToolButton>

namespace dd {

TrendControls::TrendControls(QWidget *parent)
    : QWidget(parent)
    , m_recordButton(new QPushButton(this))
    , m_pauseButton(new QPushButton(this))
    , m_resetZoomButton(new QPushButton(this))
    , m_windowLabel(new QLabel(this))
    , m_windowCombo(new QComboBox(this))
    , m_rateLabel(new QLabel(this))
    , m_rateSpin(new QDoubleSpinBox(this))
    , m_exportButton(new QToolButton(this))
    , m_exportAllAction(nullptr)
    , m_exportWindowAction(nullptr)
    , m_exportPngAction(nullptr)
    , m_exportSvgAction(nullptr)
{
    m_recordButton->setObjectName(QStringLiteral("trendRecord"));
    m_recordButton->setCheckable(true);
    connect(m_recordButton, &QPushButton::toggled, this, [this](bool on) {
        retranslateUi();
        emit recordToggled(on);
    });
    m_pauseButton->setCheckable(true);
    connect(m_pauseButton, &QPushButton::toggled, this, [this](bool on) {
        m_pauseButton->setText(on ? tr("Resume") : tr("Pause"));
        emit pauseToggled(on);
    });
    m_resetZoomButton->setEnabled(false);
    connect(m_resetZoomButton, &QPushButton::clicked, this, &TrendControls::resetZoomClicked);

    for (int s : windowChoicesSeconds())
        m_windowCombo->addItem(QString(), s);
    m_windowCombo->setCurrentIndex(1); // 30 s
    m_windowLabel->setBuddy(m_windowCombo);
    connect(m_windowCombo, &QComboBox::currentIndexChanged, this, [this] { emit windowChanged(windowSeconds()); });

    m_rateSpin->setRange(0.1, 1000.0);
    m_rateSpin->setDecimals(1);
    m_rateSpin->setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
    m_rateSpin->setValue(10.0);
    m_rateSpin->setKeyboardTracking(false); // one signal when the user is done typing
    m_rateLabel->setBuddy(m_rateSpin);
    connect(m_rateSpin, &QDoubleSpinBox::valueChanged, this, &TrendControls::sampleRateChanged);

    m_exportButton->setObjectName(QStringLiteral("trendExport"));
    m_exportButton->setPopupMode(QToolButton::InstantPopup);
    auto *menu = new QMenu(m_exportButton);
    m_exportAllAction = menu->addAction(QString());
    m_exportWindowAction = menu->addAction(QString());
    menu->addSeparator();
    m_exportPngAction = menu->addAction(QString());
    m_exportSvgAction = menu->addAction(QString());
    m_exportButton->setMenu(menu);
    connect(m_exportAllAction, &QAction::triggered, this, [this] { emit exportCsvRequested(true); });
    connect(m_exportWindowAction, &QAction::triggered, this, [this] { emit exportCsvRequested(false); });
    connect(m_exportPngAction, &QAction::triggered, this, &TrendControls::exportPngRequested);
    connect(m_exportSvgAction, &QAction::triggered, this, &TrendControls::exportSvgRequested);

    auto *row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(m_recordButton);
    row->addWidget(m_pauseButton);
    row->addWidget(m_resetZoomButton);
    row->addSpacing(8);
    row->addWidget(m_windowLabel);
    row->addWidget(m_windowCombo);
    row->addSpacing(8);
    row->addWidget(m_rateLabel);
    row->addWidget(m_rateSpin);
    row->addStretch(1);
    row->addWidget(m_exportButton);
    retranslateUi();
}

void TrendControls::retranslateUi()
{
    m_recordButton->setText(m_recordButton->isChecked() ? tr("Stop recording") : tr("Record"));
    m_recordButton->setToolTip(m_recordButton->isChecked()
                                   ? tr("Recording: the drive is sampled whatever tab or drive is shown")
                                   : tr("Start recording the checked channels"));
    m_pauseButton->setText(m_pauseButton->isChecked() ? tr("Resume") : tr("Pause"));
    m_pauseButton->setToolTip(tr("Freeze the plot; recording continues in the background"));
    m_resetZoomButton->setText(tr("Reset zoom"));
    m_resetZoomButton->setToolTip(tr("Show the selected time window again"));
    m_windowLabel->setText(tr("&Window:"));
    const QStringList names{tr("10 s"), tr("30 s"), tr("1 min"), tr("2 min"), tr("5 min"), tr("10 min")};
    for (int i = 0; i < m_windowCombo->count() && i < names.size(); ++i)
        m_windowCombo->setItemText(i, names.at(i));
    m_rateLabel->setText(tr("&Rate:"));
    m_rateSpin->setSuffix(tr(" Hz"));
    m_rateSpin->setToolTip(tr("How often the drive is read; the default is what the link can carry"));
    m_exportButton->setText(tr("Export"));
    m_exportButton->setToolTip(tr("Save the checked channels' real values as CSV, or the plot as an image"));
    m_exportAllAction->setText(tr("CSV, whole recording…"));
    m_exportWindowAction->setText(tr("CSV, visible window…"));
    m_exportPngAction->setText(tr("Plot as PNG…"));
    m_exportSvgAction->setText(tr("Plot as SVG…"));
}

void TrendControls::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

QList<int> TrendControls::windowChoicesSeconds()
{
    return {10, 30, 60, 120, 300, 600};
}

int TrendControls::windowSeconds() const
{
    return m_windowCombo->currentData().toInt();
}

void TrendControls::setWindowSeconds(int seconds)
{
    const QList<int> choices = windowChoicesSeconds();
    int best = 0;
    for (int i = 1; i < choices.size(); ++i) {
        if (std::abs(choices.at(i) - seconds) < std::abs(choices.at(best) - seconds))
            best = i;
    }
    m_windowCombo->setCurrentIndex(best);
}

double TrendControls::sampleRate() const
{
    return m_rateSpin->value();
}

void TrendControls::setSampleRate(double hz)
{
    const QSignalBlocker block(m_rateSpin);
    m_rateSpin->setValue(hz);
}

void TrendControls::setPaused(bool paused)
{
    const QSignalBlocker block(m_pauseButton);
    m_pauseButton->setChecked(paused);
    m_pauseButton->setText(paused ? tr("Resume") : tr("Pause"));
}

void TrendControls::setRecording(bool recording)
{
    const QSignalBlocker block(m_recordButton);
    m_recordButton->setChecked(recording);
    retranslateUi();
}

bool TrendControls::isRecording() const
{
    return m_recordButton->isChecked();
}

void TrendControls::setZoomed(bool zoomed)
{
    m_resetZoomButton->setEnabled(zoomed);
}

} // namespace dd
