#include "ui/panels/motion/motionpanel.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/drivereply.h"
#include "core/protocol/familytraits.h"
#include "ui/common/displaytext.h"

#include <QComboBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPointer>
#include <QPushButton>
#include <QRadioButton>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>
#include <limits>

namespace dd {

namespace {
constexpr int kMaxCount = std::numeric_limits<qint32>::max(); // int32 moves (both families)

// A row of `widgets`, left-aligned, at the top of a group box made by makeGroup().
void insertRow(QGroupBox *box, const QList<QWidget *> &widgets)
{
    auto *row = new QHBoxLayout;
    for (QWidget *w : widgets)
        row->addWidget(w);
    row->addStretch(1);
    qobject_cast<QVBoxLayout *>(box->layout())->insertLayout(0, row);
}

// Enabled without a reason; otherwise disabled with the reason as tooltip.
void setAvailable(const QList<QWidget *> &widgets, const QString &reason)
{
    for (QWidget *w : widgets) {
        w->setEnabled(reason.isEmpty());
        w->setToolTip(reason);
    }
}

// The reason written under a group box (not when the banner already says it).
void showReason(QLabel *label, const QString &reason, bool shown)
{
    label->setText(reason);
    label->setVisible(!reason.isEmpty() && shown);
}

QSpinBox *spinBox(QWidget *parent, const QString &objectName, int minimum, int maximum, int value)
{
    auto *s = new QSpinBox(parent);
    s->setObjectName(objectName);
    s->setRange(minimum, maximum);
    s->setValue(value);
    s->setAccelerated(true);
    s->setKeyboardTracking(false);
    return s;
}
} // namespace

MotionPanel::SpeedRange MotionPanel::speedRange(Family family)
{
    const FamilyTraits &t = familyTraits(family);
    SpeedRange r;
    r.maximum = t.maxSpeed;
    r.jogDefault = t.jogSpeed;
    r.moveDefault = t.moveSpeed;
    return r;
}

MotionPanel::MotionPanel(const DriveContext &context, QWidget *parent)
    : DrivePanel(context, parent)
{
    const SpeedRange range = speedRange(context.family);

    m_banner = createReasonLabel(this);
    m_banner->setObjectName(QStringLiteral("motionUnsupported"));
    m_state = new QLabel(this);
    m_position = new QLabel(this);
    m_position->setObjectName(QStringLiteral("motionPosition"));
    m_position->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_readout = new MotionReadout(context, this);
    m_powerOffNotice = new QWidget(this);
    m_powerOffNotice->setObjectName(QStringLiteral("powerOffNotice"));
    m_powerOffText = new QLabel(m_powerOffNotice);
    m_powerOffText->setObjectName(QStringLiteral("powerOffText"));
    m_powerOffText->setWordWrap(true);
    m_powerOffText->setStyleSheet(QStringLiteral("color: #e65100;"));
    m_powerOffEnable = new QPushButton(m_powerOffNotice);
    m_powerOffEnable->setObjectName(QStringLiteral("powerOffEnable"));
    auto *noticeRow = new QHBoxLayout(m_powerOffNotice);
    noticeRow->setContentsMargins(0, 0, 0, 0);
    noticeRow->addWidget(m_powerOffText, 1);
    noticeRow->addWidget(m_powerOffEnable);
    m_powerOffNotice->hide();
    if (context.hub)
        connect(context.hub, &DriveHub::stopAllSent, this, [this] {
            ++m_stopsSent;
            m_lastStopWasStop = true;
        });

    // Made in this order, which is the Tab order.
    buildPowerBox();
    buildJogBox(range);
    buildMoveBox(range);
    buildHomeBox();
    buildPositionBox();
    buildStopButton();
    layOut();

    retranslate();
}

void MotionPanel::buildPowerBox()
{
    m_powerBox = makeGroup(QStringLiteral("powerBox"), &m_powerReason);
    m_enable = new QPushButton(m_powerBox);
    m_enable->setObjectName(QStringLiteral("enableButton"));
    m_disable = new QPushButton(m_powerBox);
    m_disable->setObjectName(QStringLiteral("disableButton"));
    insertRow(m_powerBox, {m_enable, m_disable});
    m_powerResult = makeResultLabel(m_powerBox, QStringLiteral("powerResult"));
    const auto enable = [this] {
        m_powerDone = 0;
        m_powerAsked = 1;
        runCommand([] { return tr("Enable"); }, [](Drive &d) { return d.setEnabled(true); }, m_powerResult);
    };
    connect(m_enable, &QPushButton::clicked, this, enable);
    connect(m_powerOffEnable, &QPushButton::clicked, this, enable);
    connect(m_disable, &QPushButton::clicked, this, [this] {
        m_powerDone = 0;
        m_powerAsked = -1;
        runCommand([] { return tr("Disable"); }, [](Drive &d) { return d.setEnabled(false); }, m_powerResult);
    });
}

void MotionPanel::buildJogBox(const SpeedRange &range)
{
    m_jogBox = makeGroup(QStringLiteral("jogBox"), &m_jogReason);
    m_jogSpeedLabel = new QLabel(m_jogBox);
    m_jogSpeed = spinBox(m_jogBox, QStringLiteral("jogSpeed"), range.minimum, range.maximum, range.jogDefault);
    m_jogSpeedLabel->setBuddy(m_jogSpeed);
    m_jogMinus = new JogButton(-1, m_jogBox);
    m_jogMinus->setObjectName(QStringLiteral("jogMinus"));
    m_jogPlus = new JogButton(+1, m_jogBox);
    m_jogPlus->setObjectName(QStringLiteral("jogPlus"));
    m_jogState = new QLabel(m_jogBox);
    m_jogState->setObjectName(QStringLiteral("jogState"));
    m_jogHint = new QLabel(m_jogBox);
    m_jogHint->setWordWrap(true);
    auto *jogRow = new QHBoxLayout;
    jogRow->addWidget(m_jogSpeedLabel);
    jogRow->addWidget(m_jogSpeed);
    jogRow->addSpacing(12);
    jogRow->addWidget(m_jogMinus);
    jogRow->addWidget(m_jogPlus);
    jogRow->addStretch(1);
    auto *jogLayout = qobject_cast<QVBoxLayout *>(m_jogBox->layout());
    jogLayout->insertLayout(0, jogRow);
    jogLayout->insertWidget(1, m_jogState);
    jogLayout->insertWidget(2, m_jogHint);
    connectJogButtons();
}

void MotionPanel::connectJogButtons()
{
    const DriveContext &c = context();
    for (JogButton *b : {m_jogMinus, m_jogPlus}) {
        b->setDrive(c.hub, c.connectionId, c.address);
    }
    // How a jog ended when no stop command was confirmed: what stops the axis now.
    if (c.hub)
        connect(c.hub, &DriveHub::jogEnded, this, [this](int id, int address, const JogEnd &end) {
            if (id != this->context().connectionId || address != this->context().address
                || end.stoppedBy == JogEnd::StoppedBy::Command)
                return;
            m_jogState->setText(end.message);
            reportError({end.linkLost ? ErrorCode::LinkClosed : ErrorCode::Timeout, end.message});
        });
    for (JogButton *b : {m_jogMinus, m_jogPlus}) {
        b->setMinimumHeight(40);
        b->setSpeed(m_jogSpeed->value());
        connect(b, &JogButton::jogStarted, this, &MotionPanel::onJogStarted);
        connect(b, &JogButton::jogStopped, this, &MotionPanel::onJogStopped);
        connect(b, &JogButton::errorOccurred, this, &MotionPanel::reportError);
    }
    connect(m_jogSpeed, &QSpinBox::valueChanged, this, [this](int v) {
        m_jogMinus->setSpeed(v);
        m_jogPlus->setSpeed(v);
    });
}

void MotionPanel::buildMoveBox(const SpeedRange &range)
{
    m_moveBox = makeGroup(QStringLiteral("moveBox"), &m_moveReason);
    m_relative = new QRadioButton(m_moveBox);
    m_relative->setObjectName(QStringLiteral("moveRelative"));
    m_absolute = new QRadioButton(m_moveBox);
    m_absolute->setObjectName(QStringLiteral("moveAbsolute"));
    m_relative->setChecked(true);
    m_moveValue = spinBox(m_moveBox, QStringLiteral("moveValue"), -kMaxCount, kMaxCount, 0);
    m_moveSpeedLabel = new QLabel(m_moveBox);
    m_moveSpeed = spinBox(m_moveBox, QStringLiteral("moveSpeed"), range.minimum, range.maximum, range.moveDefault);
    m_moveSpeedLabel->setBuddy(m_moveSpeed);
    m_moveButton = new QPushButton(m_moveBox);
    m_moveButton->setObjectName(QStringLiteral("moveButton"));
    // Three short rows rather than two long ones: the tab's minimum width decides how much
    // of a 1280 px screen the bus dock gets (tst_overflowwalk).
    //   ○ Relative by   ○ Absolute to
    //   [ distance / target      ] [Move]
    //   Positioning speed: [speed]
    auto *moveGrid = new QGridLayout;
    moveGrid->addWidget(m_relative, 0, 0);
    moveGrid->addWidget(m_absolute, 0, 1);
    moveGrid->addWidget(m_moveValue, 1, 0, 1, 2);
    moveGrid->addWidget(m_moveButton, 1, 2);
    moveGrid->addWidget(m_moveSpeedLabel, 2, 0);
    moveGrid->addWidget(m_moveSpeed, 2, 1);
    moveGrid->setColumnStretch(3, 1);
    qobject_cast<QVBoxLayout *>(m_moveBox->layout())->insertLayout(0, moveGrid);
    m_moveResult = makeResultLabel(m_moveBox, QStringLiteral("moveResult"));
    connect(m_moveButton, &QPushButton::clicked, this, &MotionPanel::move);
}

void MotionPanel::buildHomeBox()
{
    m_homeBox = makeGroup(QStringLiteral("homeBox"), &m_homeReason);
    m_homeDirection = new QComboBox(m_homeBox);
    m_homeDirection->setObjectName(QStringLiteral("homeDirection"));
    m_homeDirection->addItems({QString(), QString()});
    m_homeButton = new QPushButton(m_homeBox);
    m_homeButton->setObjectName(QStringLiteral("homeButton"));
    insertRow(m_homeBox, {m_homeDirection, m_homeButton});
    m_homeResult = makeResultLabel(m_homeBox, QStringLiteral("homeResult"));
    connect(m_homeButton, &QPushButton::clicked, this, [this] {
        const bool positiveFirst = m_homeDirection->currentIndex() == 0;
        const Text what = [] { return tr("Home"); };
        if (const QString refused = powerOffReason(); !refused.isEmpty()) {
            showMessage(
                m_homeResult, [what, refused] { return tr("%1 refused: %2").arg(what(), refused); },
                MessageKind::Warning);
            return;
        }
        runCommand(
            what, [positiveFirst](Drive &d) { return d.home(positiveFirst); }, m_homeResult,
            MotionGoal::home(context().family));
    });
}

void MotionPanel::buildPositionBox()
{
    m_positionBox = makeGroup(QStringLiteral("positionBox"), &m_positionReason);
    m_setPositionLabel = new QLabel(m_positionBox);
    m_setPositionValue = spinBox(m_positionBox, QStringLiteral("setPositionValue"), -kMaxCount, kMaxCount, 0);
    m_setPositionLabel->setBuddy(m_setPositionValue);
    m_setPositionButton = new QPushButton(m_positionBox);
    m_setPositionButton->setObjectName(QStringLiteral("setPositionButton"));
    // The label above its value: one row of all three is the widest row of the tab.
    insertRow(m_positionBox, {m_setPositionValue, m_setPositionButton});
    qobject_cast<QVBoxLayout *>(m_positionBox->layout())->insertWidget(0, m_setPositionLabel);
    m_positionResult = makeResultLabel(m_positionBox, QStringLiteral("positionResult"));
    connect(m_setPositionButton, &QPushButton::clicked, this, [this] {
        const qint64 p = m_setPositionValue->value();
        runCommand([] { return tr("Set position"); }, [p](Drive &d) { return d.setPosition(p); }, m_positionResult);
    });
}

void MotionPanel::buildStopButton()
{
    m_stop = new QPushButton(this);
    m_stop->setObjectName(QStringLiteral("stopDriveButton"));
    m_stop->setMinimumHeight(36);
    m_stop->setStyleSheet(QStringLiteral("QPushButton:enabled { color: #b71c1c; font-weight: bold; }"));
    connect(m_stop, &QPushButton::clicked, this, &MotionPanel::stopDrive);
    m_stopHint = new QLabel(this);
    m_stopHint->setWordWrap(true);
    m_stopResult = new QLabel(this);
    m_stopResult->setObjectName(QStringLiteral("stopResult"));
    m_stopResult->setWordWrap(true);
}

void MotionPanel::layOut()
{
    auto *statusRow = new QFormLayout;
    statusRow->addRow(m_state);
    statusRow->addRow(m_position);
    auto *stopRow = new QHBoxLayout;
    stopRow->addWidget(m_stop);
    stopRow->addWidget(m_stopResult, 1);
    stopRow->addWidget(m_stopHint, 1);

    auto *left = new QVBoxLayout;
    left->addWidget(m_powerBox);
    left->addWidget(m_jogBox);
    left->addWidget(m_moveBox);
    left->addStretch(1);
    auto *right = new QVBoxLayout;
    right->addLayout(statusRow);
    right->addWidget(m_homeBox);
    right->addWidget(m_positionBox);
    right->addStretch(1);
    auto *columns = new QHBoxLayout;
    columns->addLayout(left, 3);
    columns->addLayout(right, 2);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_banner);
    layout->addWidget(m_readout);
    layout->addWidget(m_powerOffNotice);
    layout->addLayout(columns, 1);
    layout->addLayout(stopRow);
}

QGroupBox *MotionPanel::makeGroup(const QString &objectName, QLabel **reason)
{
    auto *box = new QGroupBox(this);
    box->setObjectName(objectName);
    auto *layout = new QVBoxLayout(box);
    *reason = createReasonLabel(box);
    (*reason)->setObjectName(objectName + QStringLiteral("Reason"));
    layout->addWidget(*reason);
    return box;
}

QString MotionPanel::title() const
{
    return tr("Motion");
}

QString MotionPanel::speedUnit() const
{
    return familyTraits(context().family).speedUnitText();
}

QString MotionPanel::distanceUnit() const
{
    return familyTraits(context().family).positionUnitText();
}

void MotionPanel::stopDrive()
{
    m_jogMinus->stopHold();
    m_jogPlus->stopHold();
    // A move or homing being watched goes on being watched: its line says where it stopped.
    ++m_stopsSent;
    m_lastStopWasStop = false;
    runCommand([] { return tr("Stop"); }, [](Drive &d) { return d.stop(false); }, m_stopResult);
}

QLabel *MotionPanel::makeResultLabel(QGroupBox *box, const QString &objectName)
{
    auto *label = createMessageLabel(box, objectName);
    qobject_cast<QVBoxLayout *>(box->layout())->addWidget(label);
    return label;
}

void MotionPanel::runCommand(const Text &what, DriveHub::Operation op, QLabel *result, std::optional<MotionGoal> goal)
{
    if (!context().isValid())
        return;
    const int generation = goal ? ++m_motionGeneration : m_motionGeneration;
    const int stopsAtStart = m_stopsSent;
    showMessage(
        result, [what] { return tr("%1: sending…").arg(what()); }, MessageKind::Info);
    QPointer<MotionPanel> self(this);
    QPointer<QLabel> label(result);
    context().hub->run(
        context().connectionId, context().address, std::move(op),
        [self, what, label, goal, generation, stopsAtStart](const DriveResult &r) {
            if (!self || !label)
                return;
            if (r.ok())
                self->ageProblems(); // the drive answers again: earlier failures are history
            if (!r.ok()) {
                const QString error = r.error.message;
                showMessage(
                    label, [what, error] { return tr("%1 failed: %2").arg(what(), DisplayText::sentence(error)); },
                    MessageKind::Problem);
                self->reportError(r.error);
            } else if (goal) {
                showMessage(
                    label, [what] { return tr("%1: started.").arg(what()); }, MessageKind::Info);
                self->watchMotion(generation, what, label, 0, false, *goal, stopsAtStart);
            } else {
                showMessage(
                    label, [what] { return tr("%1: done.").arg(what()); }, MessageKind::Success);
                if (label == self->m_powerResult)
                    self->m_powerDone = self->m_powerAsked;
            }
        });
}

void MotionPanel::watchMotion(int generation, const Text &what, QLabel *result, int polls, bool seenRunning,
                              const MotionGoal &goal, int stopsAtStart)
{
    // Until the drive reports the axis at rest: read its state, show where it is. A drive
    // may report the start a moment late: "at rest" counts once motion was seen, or after a
    // few reads without any.
    constexpr int PollMs = 150;
    constexpr int ReadsBeforeRestCounts = 4;
    QPointer<MotionPanel> self(this);
    QPointer<QLabel> label(result);
    QTimer::singleShot(polls == 0 ? 0 : PollMs, this, [=] {
        if (!self || !label || generation != self->m_motionGeneration)
            return;
        self->context().hub->run(
            self->context().connectionId, self->context().address, [](Drive &d) { return d.readStatus(); },
            [=](const DriveResult &r) {
                if (!self || !label || generation != self->m_motionGeneration)
                    return;
                const Text unit = [self] { return self ? self->distanceUnit() : QString(); };
                if (!r.ok()) {
                    const QString error = r.error.message;
                    showMessage(
                        label,
                        [what, error] {
                            return tr("%1: started; its state cannot be read: %2")
                                .arg(what(), DisplayText::sentence(error));
                        },
                        MessageKind::Problem);
                    return;
                }
                const DriveStatus s = r.status;
                if (s.alarmCode) {
                    showMessage(
                        label,
                        [what, s, unit] {
                            return tr("%1: stopped by alarm %2 at %3 %4.")
                                .arg(what())
                                .arg(s.alarmCode)
                                .arg(DisplayText::position(s), unit());
                        },
                        MessageKind::Problem);
                    return;
                }
                if (s.running) {
                    showMessage(
                        label,
                        [what, s, unit] {
                            return tr("%1: moving… position %2 %3").arg(what(), DisplayText::position(s), unit());
                        },
                        MessageKind::Info);
                    self->watchMotion(generation, what, label, polls + 1, true, goal, stopsAtStart);
                    return;
                }
                if (!seenRunning && polls < ReadsBeforeRestCounts && self->m_stopsSent == stopsAtStart) {
                    self->watchMotion(generation, what, label, polls + 1, false, goal, stopsAtStart);
                    return;
                }
                self->showMotionEnd(what, label, s, goal, self->m_stopsSent != stopsAtStart, self->m_lastStopWasStop);
            });
    });
}

void MotionPanel::showMotionEnd(const Text &what, QLabel *label, const DriveStatus &s, const MotionGoal &goal,
                                bool stopped, bool stoppedByStop)
{
    QPointer<MotionPanel> self(this);
    const Text unit = [self] { return self ? self->distanceUnit() : QString(); };
    const QString at = DisplayText::position(s);
    const QString off = QLocale().toString(goal.distanceToTarget(s.position));
    const QString target = QLocale().toString(goal.target());
    // What ended it: the tool bar's STOP, this drive's stop, or nothing DriveDesk sent.
    const Text how = [stopped, stoppedByStop] {
        if (!stopped)
            return tr("ended");
        return stoppedByStop ? tr("stopped by STOP") : tr("stopped by “Stop this drive”");
    };
    const Text outside = [stopped] {
        return stopped ? QString()
                       : tr(" Something outside this command stopped it: another master, the drive's own "
                            "inputs or panel, or a limit.");
    };
    if (!s.positionValid) {
        showMessage(
            label,
            [what, how] { return tr("%1: %2; the drive does not report where the axis is.").arg(what(), how()); },
            MessageKind::Warning);
        return;
    }
    switch (goal.judge(s.position, stopped)) {
    case MotionGoal::Verdict::Reached:
        showMessage(
            label,
            [what, at, unit] {
                return tr("%1: done, the axis is at rest at its target, %2 %3.").arg(what(), at, unit());
            },
            MessageKind::Success);
        return;
    case MotionGoal::Verdict::HomeFound:
        showMessage(
            label,
            [what, at, unit] {
                return tr("%1: done, the origin was found; the axis is at rest at %2 %3.").arg(what(), at, unit());
            },
            MessageKind::Success);
        return;
    case MotionGoal::Verdict::Short:
        showMessage(
            label,
            [=] {
                return tr("%1: %2 at %3 %4, %5 %4 short of the target (%6 %4).%7")
                    .arg(what(), how(), at, unit(), off, target, outside());
            },
            MessageKind::Warning);
        return;
    case MotionGoal::Verdict::Past:
        showMessage(
            label,
            [=] {
                return tr("%1: %2 at %3 %4, %5 %4 beyond the target (%6 %4).%7")
                    .arg(what(), how(), at, unit(), off, target, outside());
            },
            MessageKind::Warning);
        return;
    case MotionGoal::Verdict::HomeNotFound:
        showMessage(
            label, [=] { return tr("%1: %2 at %3 %4; the origin was not found.").arg(what(), how(), at, unit()); },
            MessageKind::Warning);
        return;
    }
}

QString MotionPanel::powerOffReason() const
{
    if (!context().can(Capability::Enable) || driveInfo().status.enabled)
        return QString();
    return tr("the power stage is off. DriveDesk does not switch it on by itself: press Enable first.");
}

void MotionPanel::updatePowerOffNotice()
{
    const QString reason = powerOffReason();
    m_powerOffNotice->setVisible(!reason.isEmpty() && driveInfo().valid);
    m_powerOffText->setText(
        tr("The power stage is off: jog, move and homing are refused until you switch it on (DriveDesk does "
           "not do it by itself)."));
    m_powerOffEnable->setText(tr("Enable"));
    // Jog cannot wait for a click to be refused: its buttons are off while the stage is.
    if (reasonFor(Capability::Jog).isEmpty()) {
        const QString why = reason.isEmpty() ? QString() : tr("Refused: %1").arg(reason);
        setAvailable({m_jogMinus, m_jogPlus}, why);
    }
}

void MotionPanel::agePowerResult(const DriveStatus &s)
{
    if (m_powerDone > 0 && !s.enabled) {
        m_powerDone = 0;
        showMessage(
            m_powerResult,
            [] { return tr("Enable: done earlier; the power stage is off now (STOP, a disable or the drive)."); },
            MessageKind::Outdated);
    } else if (m_powerDone < 0 && s.enabled) {
        m_powerDone = 0;
        showMessage(
            m_powerResult, [] { return tr("Disable: done earlier; the power stage is on again."); },
            MessageKind::Outdated);
    }
}

void MotionPanel::move()
{
    const qint64 value = m_moveValue->value();
    const qint32 speed = m_moveSpeed->value();
    const bool absolute = m_absolute->isChecked();
    const Text what = absolute ? Text([value] { return tr("Move to %1").arg(value); })
                               : Text([value] { return tr("Move by %1").arg(value); });
    if (const QString refused = powerOffReason(); !refused.isEmpty()) {
        showMessage(
            m_moveResult, [what, refused] { return tr("%1 refused: %2").arg(what(), refused); }, MessageKind::Warning);
        return;
    }
    // Where the axis is first: the target of a relative move, and which way is "short".
    showMessage(
        m_moveResult, [what] { return tr("%1: reading where the axis is…").arg(what()); }, MessageKind::Info);
    QPointer<MotionPanel> self(this);
    const Family family = context().family;
    context().hub->run(
        context().connectionId, context().address, [](Drive &d) { return d.readStatus(); },
        [self, what, value, speed, absolute, family](const DriveResult &r) {
            if (!self)
                return;
            if (!r.ok() || !r.status.positionValid) {
                const QString error = r.ok() ? tr("The drive does not report its position.") : r.error.message;
                showMessage(
                    self->m_moveResult,
                    [what, error] {
                        return tr("%1 failed: where the axis is could not be read, nothing was sent: %2")
                            .arg(what(), DisplayText::sentence(error));
                    },
                    MessageKind::Problem);
                if (!r.ok())
                    self->reportError(r.error);
                return;
            }
            const qint64 start = r.status.position;
            const qint64 target = absolute ? value : start + value;
            if (absolute)
                self->runCommand(
                    what, [value, speed](Drive &d) { return d.moveAbsolute(value, speed); }, self->m_moveResult,
                    MotionGoal::move(family, start, target));
            else
                self->runCommand(
                    what, [value, speed](Drive &d) { return d.moveRelative(value, speed); }, self->m_moveResult,
                    MotionGoal::move(family, start, target));
        });
}

void MotionPanel::onJogStarted(qint32 speed)
{
    m_jogState->setText(tr("Jogging at %1 %2 — let go to stop.")
                            .arg(speed > 0 ? QStringLiteral("+%1").arg(speed) : QString::number(speed), speedUnit()));
}

void MotionPanel::onJogStopped(JogButton::StopReason reason)
{
    using R = JogButton::StopReason;
    QString why;
    switch (reason) {
    case R::Released: why = tr("Jog stopped: the button was released."); break;
    case R::PointerLeft: why = tr("Jog stopped: the pointer left the button."); break;
    case R::FocusLost: why = tr("Jog stopped: the button lost the keyboard focus."); break;
    case R::WindowDeactivated: why = tr("Jog stopped: the window was deactivated."); break;
    case R::ApplicationInactive: why = tr("Jog stopped: DriveDesk is no longer the active application."); break;
    case R::Hidden: why = tr("Jog stopped: the Motion tab was hidden."); break;
    case R::Disabled: why = tr("Jog stopped: jogging was disabled."); break;
    case R::LinkLost: why = tr("Jog stopped: the connection was lost."); break;
    case R::LeaseExpired:
        why = tr("Jog stopped by the drive link: DriveDesk did not confirm the held button in time.");
        break;
    case R::DriveLost: why = tr("Jog ended: the drive stopped answering."); break;
    case R::JogFailed: why = tr("Jog stopped: the drive did not start."); break;
    case R::Requested: why = tr("Jog stopped."); break;
    }
    m_jogState->setText(why);
    if (reason == R::LeaseExpired)
        reportError({ErrorCode::Timeout,
                     tr("The jog of %1 was stopped because its hold was not renewed in time (the "
                        "window was busy or frozen). Press the jog button again to continue.")
                         .arg(DisplayText::driveName(context().family, context().address))});
}

void MotionPanel::activeChanged(bool active)
{
    m_readout->setPolling(active);
    if (!active) {
        m_jogMinus->stopHold(JogButton::StopReason::Hidden);
        m_jogPlus->stopHold(JogButton::StopReason::Hidden);
    }
}

void MotionPanel::driveInfoChanged(const DriveInfo &info)
{
    m_readout->setChannels(info.channels);
    updateCapabilities();
    showStatus();
}

void MotionPanel::statusChanged(const DriveStatus &status)
{
    showStatus();
    agePowerResult(status);
    updatePowerOffNotice();
}

QString MotionPanel::reasonFor(Capability c) const
{
    if (context().can(c))
        return QString();
    const QString r = driveInfo().reason(c);
    if (!r.isEmpty())
        return r;
    return driveInfo().valid ? tr("%1 is not available on this drive.").arg(DisplayText::capabilityName(c))
                             : tr("Waiting for the drive's description…");
}

void MotionPanel::updateCapabilities()
{
    const QList<Capability> motion{Capability::Enable,       Capability::Jog,  Capability::MoveRelative,
                                   Capability::MoveAbsolute, Capability::Home, Capability::SetPosition,
                                   Capability::Stop};
    bool none = true;
    for (Capability c : motion)
        none = none && !context().can(c);
    // A family without any motion gives one reason: show it once, above everything.
    const QString common = none ? reasonFor(Capability::Jog) : QString();
    m_banner->setText(common);
    m_banner->setVisible(!common.isEmpty());
    const bool perBox = common.isEmpty();

    const QString power = reasonFor(Capability::Enable);
    setAvailable({m_enable, m_disable}, power);
    showReason(m_powerReason, power, perBox);

    const QString jog = reasonFor(Capability::Jog);
    setAvailable({m_jogSpeed, m_jogMinus, m_jogPlus}, jog);
    showReason(m_jogReason, jog, perBox);

    updateMoveCapabilities(perBox);

    const QString home = reasonFor(Capability::Home);
    setAvailable({m_homeDirection, m_homeButton}, home);
    showReason(m_homeReason, home, perBox);

    const QString position = reasonFor(Capability::SetPosition);
    setAvailable({m_setPositionValue, m_setPositionButton}, position);
    showReason(m_positionReason, position, perBox);

    const QString stop = reasonFor(Capability::Stop);
    setAvailable({m_stop}, stop);
    updatePowerOffNotice();
}

void MotionPanel::updateMoveCapabilities(bool showReasons)
{
    const QString relative = reasonFor(Capability::MoveRelative);
    const QString absolute = reasonFor(Capability::MoveAbsolute);
    setAvailable({m_relative}, relative);
    setAvailable({m_absolute}, absolute);
    const bool anyMove = relative.isEmpty() || absolute.isEmpty();
    setAvailable({m_moveValue, m_moveSpeed, m_moveButton}, anyMove ? QString() : relative);
    if (!relative.isEmpty() && absolute.isEmpty())
        m_absolute->setChecked(true);
    else if (relative.isEmpty() && !absolute.isEmpty())
        m_relative->setChecked(true);
    QStringList moveReasons;
    for (const QString &r : {relative, absolute})
        if (!r.isEmpty() && !moveReasons.contains(r))
            moveReasons << r;
    showReason(m_moveReason, moveReasons.join(QLatin1Char('\n')), showReasons);
}

void MotionPanel::showStatus()
{
    const DriveStatus &s = driveInfo().status;
    m_state->setText(tr("State: %1").arg(DisplayText::summary(s)));
    m_position->setText(tr("Position: %1 %2").arg(DisplayText::position(s), distanceUnit()));
    // The live readout shows the position large when the drive offers it as a channel.
    m_position->setHidden(!m_readout->valueText(QStringLiteral("position")).isNull());
}

void MotionPanel::retranslate()
{
    m_powerBox->setTitle(tr("Power stage"));
    m_enable->setText(tr("&Enable"));
    m_enable->setWhatsThis(tr("Switch the power stage on: the motor holds its position."));
    m_disable->setText(tr("&Disable"));
    m_disable->setWhatsThis(tr("Switch the power stage off: the shaft turns freely."));

    m_jogBox->setTitle(tr("Jog (hold to run)"));
    m_jogSpeedLabel->setText(tr("Jog &speed:"));
    m_jogSpeed->setSuffix(QLatin1Char(' ') + speedUnit());
    m_jogMinus->setText(tr("◀ Jog −"));
    m_jogPlus->setText(tr("Jog + ▶"));
    m_jogHint->setText(tr("Hold a jog button (or focus it and hold Space): the axis turns only while "
                          "it is held and stops when you let go, when the window loses the focus "
                          "or when the connection drops."));
    if (!m_jogMinus->isHolding() && !m_jogPlus->isHolding())
        m_jogState->setText(tr("Not jogging."));

    m_moveBox->setTitle(tr("Move"));
    m_relative->setText(tr("&Relative by"));
    m_absolute->setText(tr("&Absolute to"));
    m_moveValue->setSuffix(QLatin1Char(' ') + distanceUnit());
    m_moveSpeedLabel->setText(tr("Positioning speed:"));
    m_moveSpeed->setSuffix(QLatin1Char(' ') + speedUnit());
    m_moveButton->setText(tr("&Move"));

    m_homeBox->setTitle(tr("Homing"));
    m_homeDirection->setItemText(0, tr("Search positive direction first"));
    m_homeDirection->setItemText(1, tr("Search negative direction first"));
    m_homeButton->setText(tr("&Home"));

    m_positionBox->setTitle(tr("Position"));
    m_setPositionLabel->setText(tr("Set the current position to:"));
    m_setPositionValue->setSuffix(QLatin1Char(' ') + distanceUnit());
    m_setPositionButton->setText(tr("Se&t"));

    m_stop->setText(tr("Stop this drive"));
    m_stopHint->setText(tr("STOP in the tool bar (Esc or F12) stops every drive on every connection."));
    m_readout->retranslate();
    updateCapabilities();
    showStatus();
}

} // namespace dd
