#include "ui/panels/tuning/steptestcontrols.h"
#include "ui/common/displaytext.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace dd {

namespace {
QDoubleSpinBox *stepSpin(QWidget *parent, const char *name, double max, double value, int decimals)
{
    auto *s = new QDoubleSpinBox(parent);
    s->setObjectName(QLatin1String(name));
    s->setRange(0.0, max);
    s->setDecimals(decimals);
    s->setValue(value);
    return s;
}
} // namespace

StepTestControls::StepTestControls(QWidget *parent)
    : QWidget(parent)
    , m_maxSpeed(stepSpin(this, "maxSpeed", 10000.0, 0.0, 0))
    , m_maxTravel(stepSpin(this, "maxTravel", 1e9, 0.0, 0))
    , m_maxDuration(stepSpin(this, "maxDuration", 600.0, 0.0, 1))
    , m_test(new QComboBox(this))
    , m_speed(stepSpin(this, "stepSpeed", 10000.0, 300.0, 0))
    , m_duration(stepSpin(this, "stepDuration", 600.0, 0.3, 2))
    , m_distance(stepSpin(this, "stepDistance", 1e9, 10000.0, 0))
    , m_return(new QCheckBox(this))
    , m_run(new QPushButton(this))
    , m_reason(new QLabel(this))
    , m_limitsTitle(new QLabel(this))
    , m_testTitle(new QLabel(this))
{
    m_test->setObjectName(QStringLiteral("stepTest"));
    m_run->setObjectName(QStringLiteral("runStep"));
    m_return->setObjectName(QStringLiteral("returnToStart"));
    m_return->setChecked(true);
    m_reason->setObjectName(QStringLiteral("runBlockedReason"));
    m_reason->setWordWrap(true);
    m_reason->setEnabled(false); // greyed, as the other panels' reasons
    for (QLabel *t : {m_limitsTitle, m_testTitle}) {
        QFont f = t->font();
        f.setBold(true);
        t->setFont(f);
    }
    for (int i = 0; i < 3; ++i)
        m_test->addItem(QString());
    m_limits = new QFormLayout;
    m_size = new QFormLayout;
    for (QFormLayout *f : {m_limits, m_size}) {
        f->setRowWrapPolicy(QFormLayout::WrapLongRows);
        f->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    }
    m_limits->addRow(new QLabel(this), m_maxSpeed);
    m_limits->addRow(new QLabel(this), m_maxTravel);
    m_limits->addRow(new QLabel(this), m_maxDuration);
    m_size->addRow(new QLabel(this), m_test);
    m_size->addRow(new QLabel(this), m_speed);
    m_size->addRow(new QLabel(this), m_duration);
    m_size->addRow(new QLabel(this), m_distance);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_limitsTitle);
    layout->addLayout(m_limits);
    layout->addWidget(m_testTitle);
    layout->addLayout(m_size);
    layout->addWidget(m_return);
    layout->addWidget(m_run);
    layout->addWidget(m_reason);
    layout->addStretch(1);
    for (QDoubleSpinBox *s : {m_maxSpeed, m_maxTravel, m_maxDuration, m_speed, m_duration, m_distance})
        connect(s, &QDoubleSpinBox::valueChanged, this, &StepTestControls::update);
    connect(m_test, &QComboBox::currentIndexChanged, this, &StepTestControls::update);
    connect(m_run, &QPushButton::clicked, this, [this] {
        if (m_running)
            emit stopRequested();
        else
            emit runRequested();
    });
    retranslate();
}

QString StepTestControls::testId(Test test)
{
    switch (test) {
    case Test::Velocity: return QStringLiteral("velocity-step");
    case Test::Position: return QStringLiteral("position-step");
    case Test::Reversal: return QStringLiteral("reversal");
    }
    return {};
}

StepTestControls::Request StepTestControls::request() const
{
    Request r;
    r.test = Test(qBound(0, m_test->currentIndex(), 2));
    r.speed = m_speed->value();
    r.duration = m_duration->value();
    r.distance = m_distance->value();
    r.maxSpeed = m_maxSpeed->value();
    r.maxTravel = m_maxTravel->value();
    r.maxDuration = m_maxDuration->value();
    r.returnToStart = m_return->isChecked();
    return r;
}

void StepTestControls::setRequest(const Request &r)
{
    m_test->setCurrentIndex(int(r.test));
    m_speed->setValue(r.speed);
    m_duration->setValue(r.duration);
    m_distance->setValue(r.distance);
    m_maxSpeed->setValue(r.maxSpeed);
    m_maxTravel->setValue(r.maxTravel);
    m_maxDuration->setValue(r.maxDuration);
    m_return->setChecked(r.returnToStart);
}

void StepTestControls::setAvailable(bool available, const QString &reason)
{
    m_available = available;
    m_unavailableReason = reason;
    update();
}

QString StepTestControls::blockedReason() const
{
    const Request r = request();
    QStringList unset;
    if (r.maxSpeed <= 0.0)
        unset << tr("maximum speed");
    if (r.maxTravel <= 0.0)
        unset << tr("maximum travel");
    if (r.maxDuration <= 0.0)
        unset << tr("maximum duration");
    if (!unset.isEmpty())
        return tr("Set the limits first: %1.").arg(unset.join(tr(", ")));
    if (r.speed <= 0.0)
        return tr("Give the step a speed above 0.");
    if (r.speed > r.maxSpeed)
        return tr("The step's speed %1 is above the maximum speed %2.").arg(r.speed).arg(r.maxSpeed);
    if (r.test == Test::Position) {
        if (r.distance <= 0.0)
            return tr("Give the position step a distance.");
        if (r.distance > r.maxTravel)
            return tr("The distance %1 is beyond the maximum travel %2.").arg(r.distance).arg(r.maxTravel);
    } else {
        const double total = r.test == Test::Reversal ? 2.0 * r.duration : r.duration;
        if (r.duration <= 0.0)
            return tr("Give the step a duration.");
        if (total > r.maxDuration)
            return tr("The test takes %1 s, longer than the maximum duration %2 s.").arg(total).arg(r.maxDuration);
    }
    if (!m_available)
        return m_unavailableReason;
    return {};
}

void StepTestControls::setRunning(bool running)
{
    m_running = running;
    retranslate();
}

void StepTestControls::setSpeedUnit(const QString &unit)
{
    if (unit.isEmpty() || unit == m_speedUnit)
        return;
    m_speedUnit = unit;
    retranslate();
}

void StepTestControls::update()
{
    const bool position = m_test->currentIndex() == int(Test::Position);
    m_duration->setVisible(!position);
    m_distance->setVisible(position);
    if (QWidget *l = m_size->labelForField(m_duration))
        l->setVisible(!position);
    if (QWidget *l = m_size->labelForField(m_distance))
        l->setVisible(position);
    for (QWidget *w :
         {static_cast<QWidget *>(m_maxSpeed), static_cast<QWidget *>(m_maxTravel),
          static_cast<QWidget *>(m_maxDuration), static_cast<QWidget *>(m_test), static_cast<QWidget *>(m_speed),
          static_cast<QWidget *>(m_duration), static_cast<QWidget *>(m_distance)})
        w->setEnabled(!m_running);
    const QString reason = m_running ? QString() : blockedReason();
    m_run->setEnabled(reason.isEmpty());
    m_reason->setText(reason);
    m_reason->setVisible(!reason.isEmpty());
}

void StepTestControls::retranslate()
{
    m_limitsTitle->setText(tr("Limits (none is assumed)"));
    m_testTitle->setText(tr("Test"));
    m_test->setItemText(0, tr("Velocity step"));
    m_test->setItemText(1, tr("Position step"));
    m_test->setItemText(2, tr("Reversal (+V, then −V)"));
    auto label = [](QFormLayout *form, QWidget *field, const QString &text) {
        if (auto *l = qobject_cast<QLabel *>(form->labelForField(field)))
            l->setText(text);
    };
    label(m_limits, m_maxSpeed, tr("Max. speed:"));
    label(m_limits, m_maxTravel, tr("Max. travel:"));
    label(m_limits, m_maxDuration, tr("Max. duration:"));
    label(m_size, m_test, tr("Test:"));
    label(m_size, m_speed, tr("Speed:"));
    label(m_size, m_duration, tr("Duration:"));
    label(m_size, m_distance, tr("Distance:"));
    for (QDoubleSpinBox *s : {m_maxSpeed, m_maxTravel, m_maxDuration})
        s->setSpecialValueText(tr("not set"));
    m_maxSpeed->setSuffix(QLatin1Char(' ') + DisplayText::unit(m_speedUnit));
    m_speed->setSuffix(QLatin1Char(' ') + DisplayText::unit(m_speedUnit));
    // Positions in the motion readout's unit.
    const QString positionSuffix = QLatin1Char(' ') + DisplayText::unit(QStringLiteral("pulses"));
    m_maxTravel->setSuffix(positionSuffix);
    m_distance->setSuffix(positionSuffix);
    m_maxDuration->setSuffix(tr(" s"));
    m_duration->setSuffix(tr(" s"));
    m_maxTravel->setToolTip(tr("From the start position, in the drive's position pulses."));
    m_run->setText(m_running ? tr("Stop the test") : tr("Run"));
    m_return->setText(tr("Back to the start afterwards"));
    m_return->setToolTip(tr("After a completed test the axis moves back to where it started. An aborted test "
                            "leaves it where it stopped."));
    update();
}

void StepTestControls::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        retranslate();
}

} // namespace dd
