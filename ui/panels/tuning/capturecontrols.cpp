#include "ui/panels/tuning/capturecontrols.h"
#include "ui/common/displaytext.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace dd {

namespace {
const QList<TriggerSpec::Kind> &kinds()
{
    static const QList<TriggerSpec::Kind> k{
        TriggerSpec::Kind::Now,   TriggerSpec::Kind::Rise,  TriggerSpec::Kind::Fall, TriggerSpec::Kind::Either,
        TriggerSpec::Kind::Above, TriggerSpec::Kind::Below, TriggerSpec::Kind::Alarm};
    return k;
}
const QList<CaptureSettings::Mode> &modes()
{
    static const QList<CaptureSettings::Mode> m{CaptureSettings::Mode::Single, CaptureSettings::Mode::Normal,
                                                CaptureSettings::Mode::Auto};
    return m;
}
QDoubleSpinBox *captureSpin(QWidget *parent, const char *name, double min, double max, double value, int decimals)
{
    auto *s = new QDoubleSpinBox(parent);
    s->setObjectName(QLatin1String(name));
    s->setRange(min, max);
    s->setDecimals(decimals);
    s->setValue(value);
    return s;
}
} // namespace

CaptureControls::CaptureControls(QWidget *parent)
    : QWidget(parent)
    , m_kind(new QComboBox(this))
    , m_channel(new QComboBox(this))
    , m_level(captureSpin(this, "triggerLevel", -1e9, 1e9, 0.0, 3))
    , m_pre(captureSpin(this, "preTrigger", 0.0, 100.0, 20.0, 0))
    , m_length(captureSpin(this, "recordLength", 0.01, 60.0, 0.5, 2))
    , m_mode(new QComboBox(this))
    , m_timeout(captureSpin(this, "autoTimeout", 0.1, 3600.0, 1.0, 1))
    , m_arm(new QPushButton(this))
    , m_force(new QPushButton(this))
    , m_stop(new QPushButton(this))
    , m_state(new QLabel(this))
{
    m_kind->setObjectName(QStringLiteral("triggerKind"));
    m_channel->setObjectName(QStringLiteral("triggerChannel"));
    m_mode->setObjectName(QStringLiteral("captureMode"));
    m_arm->setObjectName(QStringLiteral("armCapture"));
    m_force->setObjectName(QStringLiteral("forceTrigger"));
    m_stop->setObjectName(QStringLiteral("stopCapture"));
    m_state->setObjectName(QStringLiteral("captureState"));
    m_state->setWordWrap(true);
    for (int i = 0; i < kinds().size(); ++i)
        m_kind->addItem(QString());
    for (int i = 0; i < modes().size(); ++i)
        m_mode->addItem(QString());
    m_kind->setCurrentIndex(int(kinds().indexOf(TriggerSpec::Kind::Rise)));
    m_form = new QFormLayout;
    m_form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    m_form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    m_form->addRow(new QLabel(this), m_kind);
    m_form->addRow(new QLabel(this), m_channel);
    m_form->addRow(new QLabel(this), m_level);
    m_form->addRow(new QLabel(this), m_pre);
    m_form->addRow(new QLabel(this), m_length);
    m_form->addRow(new QLabel(this), m_mode);
    m_form->addRow(new QLabel(this), m_timeout);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_arm);
    buttons->addWidget(m_force);
    buttons->addWidget(m_stop);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(m_form);
    layout->addLayout(buttons);
    layout->addWidget(m_state);
    layout->addStretch(1);

    connect(m_kind, &QComboBox::currentIndexChanged, this, &CaptureControls::updateLevelFields);
    connect(m_mode, &QComboBox::currentIndexChanged, this, &CaptureControls::updateLevelFields);
    connect(m_arm, &QPushButton::clicked, this, &CaptureControls::armRequested);
    connect(m_force, &QPushButton::clicked, this, &CaptureControls::forceRequested);
    connect(m_stop, &QPushButton::clicked, this, &CaptureControls::stopRequested);
    retranslate();
    setRunning(false, QString());
}

void CaptureControls::setChannels(const QList<ChannelInfo> &channels)
{
    const QString current = m_channel->currentData().toString();
    m_channels = channels;
    m_channel->clear();
    for (const ChannelInfo &c : channels)
        m_channel->addItem(c.unit.isEmpty() ? c.name : tr("%1 (%2)").arg(c.name, DisplayText::unit(c.unit)), c.id);
    const int keep = m_channel->findData(current.isEmpty() ? QStringLiteral("speed") : current);
    if (keep >= 0)
        m_channel->setCurrentIndex(keep);
}

CaptureSettings CaptureControls::settings() const
{
    CaptureSettings s;
    s.trigger.kind = kinds().value(m_kind->currentIndex(), TriggerSpec::Kind::Now);
    if (s.trigger.isLevel()) {
        s.trigger.channel = m_channel->currentData().toString();
        s.trigger.level = m_level->value();
    }
    s.prePercent = m_pre->value();
    s.durationS = m_length->value();
    s.mode = modes().value(m_mode->currentIndex(), CaptureSettings::Mode::Single);
    s.timeoutS = m_timeout->value();
    return s;
}

void CaptureControls::setSettings(const CaptureSettings &s)
{
    m_kind->setCurrentIndex(int(kinds().indexOf(s.trigger.kind)));
    if (s.trigger.isLevel()) {
        const int c = m_channel->findData(s.trigger.channel);
        if (c >= 0)
            m_channel->setCurrentIndex(c);
        m_level->setValue(s.trigger.level);
    }
    m_pre->setValue(s.prePercent);
    m_length->setValue(s.durationS);
    m_mode->setCurrentIndex(int(modes().indexOf(s.mode)));
    m_timeout->setValue(s.timeoutS);
}

void CaptureControls::setRunning(bool running, const QString &state)
{
    m_arm->setEnabled(!running);
    m_force->setEnabled(running);
    m_stop->setEnabled(running);
    for (QWidget *w : {static_cast<QWidget *>(m_kind), static_cast<QWidget *>(m_channel),
                       static_cast<QWidget *>(m_level), static_cast<QWidget *>(m_pre), static_cast<QWidget *>(m_length),
                       static_cast<QWidget *>(m_mode), static_cast<QWidget *>(m_timeout)})
        w->setEnabled(!running);
    if (!running)
        updateLevelFields();
    m_state->setText(state);
    m_state->setVisible(!state.isEmpty());
}

QString CaptureControls::stateText() const
{
    return m_state->text();
}

void CaptureControls::updateLevelFields()
{
    const bool level = TriggerSpec{kinds().value(m_kind->currentIndex()), {}, 0.0}.isLevel();
    const bool running = !m_arm->isEnabled();
    m_channel->setEnabled(level && !running);
    m_level->setEnabled(level && !running);
    m_timeout->setEnabled(m_mode->currentIndex() == int(modes().indexOf(CaptureSettings::Mode::Auto)) && !running);
}

void CaptureControls::retranslate()
{
    const QStringList kindNames{
        tr("At once"),     tr("Rising through level"), tr("Falling through level"), tr("Either way through level"),
        tr("Above level"), tr("Below level"),          tr("Alarm raised")};
    for (int i = 0; i < kindNames.size(); ++i)
        m_kind->setItemText(i, kindNames.at(i));
    const QStringList modeNames{tr("Single"), tr("Normal (re-arm)"), tr("Auto (time-out)")};
    for (int i = 0; i < modeNames.size(); ++i)
        m_mode->setItemText(i, modeNames.at(i));
    auto label = [this](QWidget *field, const QString &text) {
        if (auto *l = qobject_cast<QLabel *>(m_form->labelForField(field)))
            l->setText(text);
    };
    label(m_kind, tr("Trigger:"));
    label(m_channel, tr("Channel:"));
    label(m_level, tr("Level:"));
    label(m_pre, tr("Pre-trigger:"));
    label(m_length, tr("Length:"));
    label(m_mode, tr("Mode:"));
    label(m_timeout, tr("Auto after:"));
    m_pre->setSuffix(tr(" %"));
    m_length->setSuffix(tr(" s"));
    m_timeout->setSuffix(tr(" s"));
    m_arm->setText(tr("Arm"));
    m_force->setText(tr("Force"));
    m_stop->setText(tr("Stop"));
    m_arm->setToolTip(tr("Start sampling; the capture is taken when the trigger fires."));
    m_force->setToolTip(tr("Fire the trigger now."));
    setChannels(m_channels);
}

void CaptureControls::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        retranslate();
}

} // namespace dd
