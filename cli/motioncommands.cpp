#include "cli/motioncommands.h"

#include "cli/clivalues.h"

#include "core/drive/drive.h"

#include <cmath>

namespace dd {

namespace {

// Stops the axis after an interrupted move or homing; reports how it went.
void stopAfterInterrupt(CliCommand *command, Drive *drive, CliOutput *out, std::function<void(const Error &)> done)
{
    out->note(QCoreApplication::translate("dd::Cli", "Interrupted: stopping the axis."));
    DriveReply *r = drive->stop(false);
    QObject::connect(r, &DriveReply::finished, command, [r, done = std::move(done)] {
        r->deleteLater();
        done(r->error());
    });
}

} // namespace

// --- jog --------------------------------------------------------------------------------

JogCommand::JogCommand(CliContext *c)
    : CliCommand(QStringLiteral("jog"), c)
    , m_renew(this)
    , m_duration(this)
{
    m_renew.setTimerType(Qt::PreciseTimer);
    m_duration.setSingleShot(true);
    m_duration.setTimerType(Qt::PreciseTimer);
    connect(&m_duration, &QTimer::timeout, this, [this] { stopNow(Reason::Duration); });
}

bool JogCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 1, 1, tr("a speed, e.g. jog 100 or jog -100"), error))
        return false;
    const auto speed = CliValues::integer(inv.positionals.at(0), std::numeric_limits<qint32>::min(),
                                          std::numeric_limits<qint32>::max(), tr("jog speed"), error);
    if (!speed)
        return false;
    m_speed = qint32(*speed);
    if (inv.has(QStringLiteral("duration"))) {
        const auto d = CliValues::real(inv.value(QStringLiteral("duration")), 0.001, 86400,
                                       QStringLiteral("--duration"), error);
        if (!d)
            return false;
        m_durationS = *d;
    }
    m_enable = inv.has(QStringLiteral("enable"));
    return true;
}

void JogCommand::start()
{
    if (!motionMaySwitchPowerOn(m_enable))
        return;
    Drive *d = drive();
    connect(d, &Drive::jogLeaseExpired, this, [this] {
        // The drive stopped itself; report it (the stop is already underway).
        m_stopping = true;
        m_renew.stop();
        m_duration.stop();
        fail({ErrorCode::Cancelled, tr("The jog lease ran out and the drive stopped the axis.")});
    });
    connect(d, &Drive::alarmChanged, this, [this](int code) {
        if (code != 0)
            stopNow(
                Reason::Error,
                {ErrorCode::DriveException, tr("The drive raised alarm %1 while jogging; stopped.").arg(code), code});
    });
    // Emitted before connectionLost and before a stop's reply: says what stops the axis.
    connect(d, &Drive::jogEnded, this, [this](const JogEnd &end) { m_end = end; });
    connect(d, &Drive::connectionLost, this, &JogCommand::linkLost);

    m_clock.start();
    DriveReply *r = d->jog(m_speed);
    onFinished(r, [this](DriveReply *r) {
        if (r->ok())
            return;
        const ErrorCode c = r->error().code;
        if (c == ErrorCode::NotSupported || c == ErrorCode::OutOfRange || c == ErrorCode::InvalidArgument) {
            // Refused before anything was sent: nothing moves, nothing to stop.
            m_renew.stop();
            m_duration.stop();
            return fail(r->error());
        }
        stopNow(Reason::Error, r->error());
    });
    // Renew at a third of the lease, so that one late timer never lets it lapse.
    m_renew.start(qMax(10, d->jogLeaseMs() / 3));
    connect(&m_renew, &QTimer::timeout, d, &Drive::renewJogLease);
    if (m_durationS > 0)
        m_duration.start(int(std::lround(m_durationS * 1000)));
    else
        out()->note(tr("Jogging at %1; press Ctrl-C to stop.").arg(m_speed));
}

void JogCommand::stopNow(Reason reason, const Error &error)
{
    if (isDone())
        return;
    if (m_stopping) {
        if (reason == Reason::Signal && !m_emergencySent && drive()->hasCapability(Capability::EmergencyStop)) {
            m_emergencySent = true;
            out()->note(tr("Second interrupt: emergency stop."));
            DriveReply *r = drive()->stop(true);
            connect(r, &DriveReply::finished, r, &QObject::deleteLater);
        }
        return;
    }
    m_stopping = true;
    m_reason = reason;
    m_error = error;
    m_renew.stop();
    m_duration.stop();
    onFinished(drive()->stop(false), [this](DriveReply *r) { onStopped(r); });
}

void JogCommand::onStopped(DriveReply *reply)
{
    const double ran = double(m_clock.elapsed()) / 1000.0;
    const QString why = m_reason == Reason::Duration ? QStringLiteral("duration")
        : m_reason == Reason::Signal                 ? QStringLiteral("signal")
                                                     : QStringLiteral("error");
    // What stops the axis: our stop command, the drive's own watchdog, or nothing.
    const QString axis = reply->info().value(QStringLiteral("stoppedBy")).toString();
    QJsonObject json{{QStringLiteral("speed"), m_speed},
                     {QStringLiteral("seconds"), std::round(ran * 1000) / 1000},
                     {QStringLiteral("stoppedBy"), why},
                     {QStringLiteral("stopped"), reply->ok()}};
    if (!axis.isEmpty())
        json.insert(QStringLiteral("axisStoppedBy"), axis);
    if (!reply->ok()) {
        Error e = reply->error();
        e.message = axis == QLatin1String("drive-watchdog")
            ? tr("STOP FAILED: %1 The drive's own watchdog stops the axis when it hears "
                 "nothing from us; check that it has stopped.")
                  .arg(e.message)
            : tr("STOP FAILED: %1 The axis may still be moving: use the machine's "
                 "emergency stop.")
                  .arg(e.message);
        return fail(e, json, CliExit::DriveFailed);
    }
    if (m_reason == Reason::Error)
        return fail(m_error, json);
    succeed(json,
            tr("Jogged at %1 for %2 s; stopped (%3).")
                .arg(m_speed)
                .arg(ran, 0, 'f', 2)
                .arg(m_reason == Reason::Duration ? tr("duration ended") : tr("interrupted")));
}

void JogCommand::interrupt(int signalNumber)
{
    if (!m_clock.isValid())
        return CliCommand::interrupt(signalNumber); // not moving yet
    stopNow(Reason::Signal);
}

void JogCommand::linkLost(const Error &why)
{
    m_renew.stop();
    m_duration.stop();
    m_stopping = true;
    Error e = why;
    if (e.code == ErrorCode::None)
        e.code = ErrorCode::LinkClosed;
    QJsonObject json{{QStringLiteral("speed"), m_speed},
                     {QStringLiteral("stoppedBy"), QStringLiteral("error")},
                     {QStringLiteral("stopped"), false}};
    if (m_end) {
        // The drive said what stops the axis now (its watchdog, or nothing).
        json.insert(QStringLiteral("axisStoppedBy"), stoppedById(m_end->stoppedBy));
        e.message = tr("The link was lost while jogging (%1). %2").arg(why.message, m_end->message);
    } else {
        e.message = tr("The link was lost while jogging (%1). The drive's own watchdog stops the "
                       "axis where the family has one; check it has stopped.")
                        .arg(why.message);
    }
    fail(e, json);
}

// --- move and home: run to the end ------------------------------------------------------

PositioningCommand::PositioningCommand(const QString &name, CliContext *c)
    : CliCommand(name, c)
    , m_poll(this)
{
    m_poll.setInterval(50);
    connect(&m_poll, &QTimer::timeout, this, &PositioningCommand::poll);
}

bool PositioningCommand::prepareWait(const CliInvocation &inv)
{
    m_wait = !inv.has(QStringLiteral("no-wait"));
    return true;
}

void PositioningCommand::follow(DriveReply *reply, const QJsonObject &json, const QString &text, const MotionGoal &goal)
{
    m_json = json;
    m_text = text;
    m_goal = goal;
    onFinished(reply, [this](DriveReply *r) {
        if (m_stopping)
            return;
        if (!r->ok())
            return fail(r->error(), m_json);
        if (!m_wait)
            return succeed(m_json, m_text);
        out()->note(m_text);
        m_clock.start();
        m_poll.start();
    });
}

void PositioningCommand::poll()
{
    m_poll.stop(); // one status read at a time
    onFinished(drive()->readStatus(), [this](DriveReply *r) {
        if (m_stopping || isDone())
            return;
        if (!r->ok())
            return fail(r->error(), m_json);
        const DriveStatus s = r->status();
        if (s.alarmCode != 0)
            return fail({ErrorCode::DriveException, tr("The drive raised alarm %1 during the motion.").arg(s.alarmCode),
                         s.alarmCode},
                        m_json);
        if (s.running) {
            m_sawRunning = true;
            m_idlePolls = 0;
        } else {
            ++m_idlePolls;
        }
        // At rest twice after having moved (the first status at rest can carry reads taken
        // while the axis still settled: its position would be a count off the end), or at
        // rest for a while (a short motion may be over before the first poll).
        if ((m_sawRunning && m_idlePolls >= 2) || (m_idlePolls >= 3 && m_clock.elapsed() >= 300))
            return finishAtRest(s);
        m_poll.start();
    });
}

void PositioningCommand::finishAtRest(const DriveStatus &s)
{
    QJsonObject json = m_json;
    json.insert(QStringLiteral("finished"), true);
    if (!s.positionValid) {
        json.insert(QStringLiteral("reached"), false);
        return fail({ErrorCode::Cancelled,
                     tr("The axis is at rest, but the drive does not report where: whether the %1 reached its "
                        "end is not known.")
                         .arg(m_goal.kind() == MotionGoal::Kind::Home ? tr("homing") : tr("move"))},
                    json);
    }
    json.insert(QStringLiteral("position"), double(s.position));
    const MotionGoal::Verdict v = m_goal.judge(s.position);
    const bool reached = v == MotionGoal::Verdict::Reached || v == MotionGoal::Verdict::HomeFound;
    json.insert(QStringLiteral("reached"), reached);
    if (m_goal.kind() == MotionGoal::Kind::Move)
        json.insert(QStringLiteral("target"), double(m_goal.target()));
    if (reached)
        return succeed(json,
                       m_goal.kind() == MotionGoal::Kind::Home
                           ? tr("Done; the origin was found, position %1.").arg(s.position)
                           : tr("Done; position %1.").arg(s.position));
    // Something stopped it: a STOP (DriveDesk's, another program's), the drive's inputs, a limit.
    const QString cause = tr("Something stopped it: a STOP from DriveDesk or another program, the drive's own "
                             "inputs or panel, or a limit.");
    QString what;
    switch (v) {
    case MotionGoal::Verdict::Short:
        what = tr("The move ended at %1, %2 short of the target %3.")
                   .arg(s.position)
                   .arg(m_goal.distanceToTarget(s.position))
                   .arg(m_goal.target());
        break;
    case MotionGoal::Verdict::Past:
        what = tr("The move ended at %1, %2 beyond the target %3.")
                   .arg(s.position)
                   .arg(m_goal.distanceToTarget(s.position))
                   .arg(m_goal.target());
        break;
    default: what = tr("The homing ended at %1 without finding the origin.").arg(s.position); break;
    }
    json.insert(QStringLiteral("distanceToTarget"), double(m_goal.distanceToTarget(s.position)));
    fail({ErrorCode::Cancelled, what + QLatin1Char(' ') + cause}, json);
}

void PositioningCommand::interrupt(int)
{
    if (m_stopping)
        return;
    m_stopping = true;
    m_poll.stop();
    stopAfterInterrupt(this, drive(), out(), [this](const Error &e) {
        if (e)
            return fail(e, m_json);
        fail({ErrorCode::Cancelled, tr("Interrupted; the axis was stopped.")}, m_json);
    });
}

// --- move -------------------------------------------------------------------------------

bool MoveCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 0, 0, QString(), error))
        return false;
    const bool by = inv.has(QStringLiteral("by"));
    const bool to = inv.has(QStringLiteral("to"));
    if (by == to) {
        *error = tr("move needs exactly one of --by N (relative) or --to N (absolute).");
        return false;
    }
    m_relative = by;
    const QString opt = by ? QStringLiteral("--by") : QStringLiteral("--to");
    const auto v = CliValues::integer(inv.value(by ? QStringLiteral("by") : QStringLiteral("to")),
                                      std::numeric_limits<qint32>::min(), std::numeric_limits<qint32>::max(), opt,
                                      error);
    if (!v)
        return false;
    m_target = *v;
    if (inv.has(QStringLiteral("speed"))) {
        const auto s = CliValues::integer(inv.value(QStringLiteral("speed")), 1, std::numeric_limits<qint32>::max(),
                                          QStringLiteral("--speed"), error);
        if (!s)
            return false;
        m_speed = qint32(*s);
    }
    m_enable = inv.has(QStringLiteral("enable"));
    return prepareWait(inv);
}

void MoveCommand::start()
{
    if (Drive *d = drive(); !d->hasCapability(m_relative ? Capability::MoveRelative : Capability::MoveAbsolute)) {
        // Refused before anything is sent.
        DriveReply *r = m_relative ? d->moveRelative(m_target, m_speed) : d->moveAbsolute(m_target, m_speed);
        return follow(r, {}, QString(), MotionGoal::move(d->family(), 0, m_target));
    }
    if (!motionMaySwitchPowerOn(m_enable))
        return;
    // Where the axis is first: a relative move's target, and which side of it is "short".
    onFinished(drive()->readStatus(), [this](DriveReply *status) {
        const QJsonObject json{{m_relative ? QStringLiteral("by") : QStringLiteral("to"), double(m_target)},
                               {QStringLiteral("speed"), m_speed}};
        if (!status->ok())
            return fail(status->error(), json);
        if (!status->status().positionValid)
            return fail({ErrorCode::DriveException, tr("The drive does not report its position: nothing was moved.")},
                        json);
        const qint64 start = status->status().position;
        const qint64 goal = m_relative ? start + m_target : m_target;
        Drive *d = drive();
        DriveReply *r = m_relative ? d->moveRelative(m_target, m_speed) : d->moveAbsolute(m_target, m_speed);
        follow(r, json, m_relative ? tr("Moving by %1.").arg(m_target) : tr("Moving to %1.").arg(m_target),
               MotionGoal::move(d->family(), start, goal));
    });
}

// --- home -------------------------------------------------------------------------------

bool HomeCommand::prepare(const CliInvocation &inv, QString *error)
{
    m_positive = inv.has(QStringLiteral("positive"));
    return expectArguments(inv, 0, 0, QString(), error) && prepareWait(inv);
}

void HomeCommand::start()
{
    follow(drive()->home(m_positive), {{QStringLiteral("positiveFirst"), m_positive}},
           tr("Homing (%1 direction first).").arg(m_positive ? tr("positive") : tr("negative")),
           MotionGoal::home(drive()->family()));
}

} // namespace dd
