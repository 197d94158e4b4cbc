#include "core/tuning/steptest.h"

#include "core/drive/drive.h"
#include "core/params/parameterdictionary.h"
#include "core/tuning/capturesession.h"

#include <QDateTime>
#include <cmath>

namespace dd {

namespace {
constexpr int PollMs = 50;
constexpr int StopConfirmMs = 3000; // the axis must be seen at rest this soon after a stop
// The time between a position read and the stop taking effect that the travel watch allows
// for beyond two sample intervals: the stop command's way to the drive.
constexpr double StopReactionS = 0.010;
// The speed in counts/s is measured over at least this long (the position's quantisation).
constexpr double SpeedWindowS = 0.004;
// A position step or the return has arrived within this many counts of its target (or 0.5 %
// of the distance); short of that the axis was stopped by something else.
constexpr double ArrivalCounts = 10.0;

bool offers(const Drive *drive, const QString &channel)
{
    for (const ChannelInfo &i : drive->channels())
        if (i.id == channel)
            return true;
    return false;
}

QString unitOf(const Drive *drive, const QString &channel)
{
    for (const ChannelInfo &i : drive->channels())
        if (i.id == channel)
            return i.unit;
    return {};
}

// The part of a reversal's capture around its reversal: from the middle of the first
// segment on, with time 0 at the reversal (the samples before it are its "pre-trigger").
CaptureData reversalPart(const CaptureData &c, double reversalAt)
{
    CaptureData out;
    out.channels = c.channels;
    out.triggerSource = c.triggerSource;
    out.columns.resize(c.columns.size());
    for (int i = 0; i < c.time.size(); ++i) {
        const double t = c.time.at(i);
        if (t < reversalAt / 2.0)
            continue;
        out.time.append(t - reversalAt);
        for (int k = 0; k < c.columns.size(); ++k)
            out.columns[k].append(c.columns.at(k).value(i, std::nan("")));
        if (t < reversalAt)
            ++out.preTriggerSamples;
    }
    out.interval = IntervalStats::of(out.time);
    out.gaps = CaptureGap::of(out.time);
    return out;
}
} // namespace

StepTest::StepTest(Drive *drive, QObject *parent)
    : QObject(parent)
    , m_drive(drive)
    , m_renew(this)
    , m_step(this)
    , m_limit(this)
    , m_retry(this)
{
    qRegisterMetaType<dd::StepResult>();
    m_renew.setTimerType(Qt::PreciseTimer);
    m_step.setSingleShot(true);
    m_step.setTimerType(Qt::PreciseTimer);
    m_limit.setSingleShot(true);
    m_retry.setSingleShot(true);
    connect(&m_step, &QTimer::timeout, this, &StepTest::onStepTimer);
    connect(&m_limit, &QTimer::timeout, this, [this] {
        abortWith(
            QStringLiteral("duration-limit"),
            {ErrorCode::Cancelled,
             tr("The motion was not at rest within the maximum duration of %1 s; stopped.").arg(m_limits.maxDurationS)});
    });
    if (!drive)
        return;
    connect(&m_renew, &QTimer::timeout, drive, &Drive::renewJogLease);
    connect(drive, &Drive::alarmChanged, this, [this](int code) {
        if (code == 0 || !isRunning())
            return;
        if (m_aborting && m_result.abortCause == QLatin1String("external-stop"))
            return alarmWasTheCause(code); // the drive stopped because of its alarm
        if (!m_result.moved)               // before the motion: a refusal, not an abort
            return refuse({ErrorCode::DriveException,
                           tr("Alarm %1 is active: clear it first. No motion was sent.").arg(code), code});
        abortOnAlarm(code);
    });
    connect(drive, &Drive::statusChanged, this, &StepTest::onStatus);
    connect(drive, &Drive::stopRequested, this, [this] {
        if (isRunning() && !m_ownStop && m_result.moved)
            abortWith(QStringLiteral("stop"), {ErrorCode::Cancelled, tr("STOP: the step test was stopped.")});
    });
    connect(drive, &Drive::jogLeaseExpired, this, [this] {
        if (isRunning())
            abortWith(QStringLiteral("lease-expired"),
                      {ErrorCode::Cancelled, tr("The jog lease ran out and the drive stopped the axis.")});
    });
    connect(drive, &Drive::jogEnded, this, [this](const JogEnd &end) { m_jogEnd = end.message; });
    connect(drive, &Drive::connectionLost, this, &StepTest::linkLost);
}

void StepTest::linkLost(const Error &why)
{
    if (!isRunning())
        return;
    m_linkLost = true;
    abortWith(QStringLiteral("link-lost"),
              {ErrorCode::LinkClosed, tr("The link was lost during the step test (%1).").arg(why.message)});
}

StepTest::~StepTest()
{
    // Gone mid-test (a closed tab): the axis must not go on moving on its own.
    if (isRunning() && m_result.moved && m_drive) {
        m_ownStop = true;
        DriveReply *r = m_drive->stop(false);
        connect(r, &DriveReply::finished, r, &QObject::deleteLater);
    }
}

QString StepTest::phaseId(Phase phase)
{
    switch (phase) {
    case Phase::Idle: return QStringLiteral("idle");
    case Phase::Preparing: return QStringLiteral("preparing");
    case Phase::Arming: return QStringLiteral("arming");
    case Phase::Moving: return QStringLiteral("moving");
    case Phase::Stopping: return QStringLiteral("stopping");
    case Phase::Returning: return QStringLiteral("returning");
    case Phase::Done: return QStringLiteral("done");
    }
    return {};
}

QStringList StepTest::channelsFor(const Drive *drive, StepSpec::Kind kind)
{
    QStringList wanted;
    if (kind == StepSpec::Kind::Position)
        wanted = {QStringLiteral("position"), QStringLiteral("position-error"), QStringLiteral("speed"),
                  QStringLiteral("torque"), QStringLiteral("current")};
    else
        wanted = {QStringLiteral("speed"), QStringLiteral("speed-command"), QStringLiteral("torque"),
                  QStringLiteral("current"), QStringLiteral("position")};
    QStringList out;
    if (!drive)
        return out;
    for (const QString &c : std::as_const(wanted))
        if (offers(drive, c))
            out << c;
    // A jog is watched on the drive's speed command (CommandWatch); a drive without one
    // that reports its running state as a channel (shuoke) is watched on that.
    if (kind != StepSpec::Kind::Position && !out.contains(QStringLiteral("speed-command"))
        && offers(drive, QStringLiteral("status")))
        out << QStringLiteral("status");
    return out;
}

Error StepTest::check(const Drive *drive, const StepSpec &spec, const StepLimits &limits)
{
    if (Error e = spec.check())
        return e;
    if (Error e = limits.check(spec))
        return e;
    if (!drive)
        return {ErrorCode::InvalidArgument, tr("No drive to test.")};
    QList<Capability> needed = {Capability::Monitor, Capability::Stop};
    needed << (spec.kind == StepSpec::Kind::Position ? Capability::MoveRelative : Capability::Jog);
    for (Capability c : needed)
        if (!drive->hasCapability(c))
            return {
                ErrorCode::NotSupported,
                tr("This drive cannot run a %1 step: %2").arg(StepSpec::kindId(spec.kind), drive->unsupportedReason(c))};
    if (spec.returnToStart && !drive->hasCapability(Capability::MoveAbsolute)
        && !drive->hasCapability(Capability::MoveRelative))
        return {ErrorCode::NotSupported,
                tr("This drive cannot move back to the start position; run the test without returning.")};
    for (const QString &c : {QStringLiteral("speed"), QStringLiteral("position")})
        if (!offers(drive, c))
            return {ErrorCode::NotSupported,
                    tr("This drive offers no %1 channel, which the step test's limits are watched on.").arg(c)};
    for (const QString &c : spec.channels)
        if (!offers(drive, c))
            return {ErrorCode::InvalidArgument, tr("This drive has no channel %1.").arg(c)};
    // The travel and time at full speed, before the stop (the stop needs the drive's
    // deceleration, read with the tuning parameters: planWithDeceleration()).
    const QString unit = unitOf(drive, QStringLiteral("speed"));
    const double k = StepPlan::countsPerSpeedUnit(unit, spec.countsPerRev);
    if (!(k > 0.0))
        return {ErrorCode::NotSupported,
                tr("This drive's speed unit \"%1\" is not one DriveDesk can relate to positions: the test's travel "
                   "cannot be predicted.")
                    .arg(unit)};
    return StepPlan::predict(spec, k).check(limits);
}

Error StepTest::start(const StepSpec &spec, const StepLimits &limits)
{
    if (isRunning())
        return {ErrorCode::Busy, tr("A step test is already running.")};
    if (Error e = check(m_drive, spec, limits))
        return e;
    ++m_generation;
    m_spec = spec;
    m_limits = limits;
    m_channels = spec.channels.isEmpty() ? channelsFor(m_drive, spec.kind) : spec.channels;
    for (const QString &c : {QStringLiteral("speed"), QStringLiteral("position")})
        if (!m_channels.contains(c))
            m_channels << c; // the limits are watched on them
    m_result = StepResult();
    m_capture = CaptureData();
    m_haveCapture = false;
    m_motionDone = false;
    m_restConfirmed = false;
    m_startKnown = false;
    m_snapshot.clear();
    m_segment = 0;
    m_reversalAt = 0.0;
    m_stopSent = false;
    m_aborting = false;
    m_linkLost = false;
    m_ownStop = false;
    m_jogEnd.clear();
    m_watch.idle();
    m_recent.clear();
    m_lastSampleT = -1.0;
    m_sampleGap = 0.0;
    m_countsPerS = 0.0;
    m_plan = StepPlan::predict(
        spec, StepPlan::countsPerSpeedUnit(unitOf(m_drive, QStringLiteral("speed")), spec.countsPerRev));
    setPhase(Phase::Preparing, tr("Reading the drive's state and tuning parameters."));
    readState();
    return {};
}

void StepTest::abort(const QString &reason)
{
    if (!isRunning())
        return;
    abortWith(QStringLiteral("stop"),
              {ErrorCode::Cancelled, reason.isEmpty() ? tr("STOP: the step test was stopped.") : reason});
}

void StepTest::setPhase(Phase phase, const QString &message)
{
    m_phase = phase;
    emit progress(phase, message);
}

void StepTest::watch(DriveReply *reply, std::function<void(DriveReply *)> handler)
{
    const quint64 generation = m_generation;
    connect(reply, &DriveReply::finished, this, [this, reply, generation, handler = std::move(handler)] {
        reply->deleteLater();
        if (generation == m_generation)
            handler(reply);
    });
}

void StepTest::readState()
{
    watch(m_drive->readStatus(), [this](DriveReply *r) {
        if (m_phase != Phase::Preparing)
            return;
        if (!r->ok()) {
            m_result.error = r->error();
            m_result.reason = tr("Could not read the drive's state: %1").arg(r->error().message);
            return finish(StepResult::Outcome::Failed);
        }
        const DriveStatus s = r->status();
        if (s.alarmCode != 0)
            return refuse({ErrorCode::DriveException,
                           tr("Alarm %1 is active: clear it first. No motion was sent.").arg(s.alarmCode),
                           s.alarmCode});
        if (s.positionValid) {
            m_start = s.position;
            m_startKnown = true;
        }
        readSnapshot();
    });
}

void StepTest::readSnapshot()
{
    const ParameterDictionary &dict = m_drive->parameterDictionary();
    QList<int> indices;
    for (const TuningEntry &e : dict.tuning())
        indices << e.index;
    if (indices.isEmpty())
        return planWithDeceleration();
    watch(m_drive->readParameters(indices), [this](DriveReply *r) {
        if (m_phase != Phase::Preparing)
            return;
        if (!r->ok()) {
            m_result.error = r->error();
            m_result.reason = tr("Could not read the tuning parameters: %1").arg(r->error().message);
            return finish(StepResult::Outcome::Failed);
        }
        const ParameterDictionary &d = m_drive->parameterDictionary();
        for (const TuningEntry &e : d.tuning())
            if (r->parameters().contains(e.index))
                m_snapshot.append({e.index, d.byIndex(e.index)->key, e.role, r->parameters().value(e.index)});
        planWithDeceleration();
    });
}

void StepTest::planWithDeceleration()
{
    // The drive's deceleration where its dictionary names it and the snapshot read it.
    const ParameterDictionary &d = m_drive->parameterDictionary();
    double decel = 0.0;
    QString source;
    for (const QString &role : {QStringLiteral("deceleration"), QStringLiteral("acceleration")}) {
        for (const TuningSnapshotEntry &e : std::as_const(m_snapshot)) {
            if (e.role != role || decel > 0.0)
                continue;
            const ParameterInfo *info = d.byIndex(e.index);
            decel = StepPlan::decelFromParameter(info ? info->unit : QString(), double(e.value));
            if (decel > 0.0)
                source = tr("%1 %2 %3, the drive's").arg(e.key).arg(e.value).arg(info->unit);
        }
    }
    if (!(decel > 0.0)) {
        decel = std::abs(double(m_spec.speed)) / StepPlan::AssumedStopS;
        source = tr("assumed: a stop from the test's speed within %1 s; the dictionary names no deceleration")
                     .arg(StepPlan::AssumedStopS);
    }
    m_plan = StepPlan::predict(m_spec, m_plan.countsPerSpeedUnitS, decel);
    m_plan.decelSource = source;
    m_result.predictedTravel = m_plan.travel;
    m_result.predictedSeconds = m_plan.seconds;
    m_result.decelSource = source;
    if (Error e = m_plan.check(m_limits)) {
        e.message += QLatin1Char(' ') + tr("No motion was sent.");
        return refuse(e);
    }
    arm();
}

void StepTest::refuse(const Error &error)
{
    if (!isRunning())
        return;
    m_aborting = true;
    m_result.abortCause = QStringLiteral("refused");
    m_result.error = error;
    m_result.reason = error.message;
    m_result.stopConfirmed = true;
    finish(StepResult::Outcome::Failed);
}

void StepTest::arm()
{
    delete m_session;
    m_session = new CaptureSession(m_drive, this);
    CaptureSettings settings;
    settings.trigger.kind = TriggerSpec::Kind::MotionStart;
    // A position step without a record of its own records until the axis is at rest (then
    // settleS more: finishNow()), at most for the maximum duration.
    const double record = m_spec.recordSeconds() > 0.0 ? m_spec.recordSeconds() : m_limits.maxDurationS;
    settings.durationS = m_spec.preS + record;
    settings.prePercent = 100.0 * m_spec.preS / settings.durationS;
    settings.mode = CaptureSettings::Mode::Single;
    m_settings = settings;
    connect(m_session, &CaptureSession::watching, this, &StepTest::sendMotion);
    connect(m_session, &CaptureSession::sampled, this, &StepTest::onSample);
    connect(m_session, &CaptureSession::captured, this, &StepTest::onCaptured);
    connect(m_session, &CaptureSession::failed, this, [this](const Error &e) {
        abortWith(QStringLiteral("capture-failed"),
                  {e.code == ErrorCode::None ? ErrorCode::Timeout : e.code, tr("The capture failed: %1").arg(e.message),
                   e.driveCode});
    });
    setPhase(Phase::Arming, tr("Capturing %1 before the motion.").arg(m_channels.join(QStringLiteral(", "))));
    m_session->start(settings, m_channels);
}

void StepTest::sendMotion()
{
    if (m_phase != Phase::Arming || m_aborting)
        return;
    if (!m_startKnown) {
        abortWith(QStringLiteral("travel-limit"),
                  {ErrorCode::NotSupported, tr("The start position is unknown: the travel limit cannot be watched.")});
        return;
    }
    m_result.positionKnown = true;
    m_result.startPosition = m_start;
    m_result.endPosition = m_start;
    setPhase(Phase::Moving,
             m_spec.kind == StepSpec::Kind::Position
                 ? tr("Moving by %1 at %2.").arg(m_spec.distance).arg(m_spec.speed)
                 : tr("Running at %1 for %2 s.").arg(m_spec.speed).arg(m_spec.durationS));
    m_result.moved = true;
    m_motionClock.start();
    m_limit.start(int(std::lround(m_limits.maxDurationS * 1000.0)));
    DriveReply *r = nullptr;
    if (m_spec.kind == StepSpec::Kind::Position) {
        r = m_drive->moveRelative(m_spec.distance, m_spec.speed);
    } else {
        m_watch.expectSpeed(m_spec.speed, true);
        r = m_drive->jog(m_spec.speed);
        m_renew.start(qMax(10, m_drive->jogLeaseMs() / 3));
        m_step.start(int(std::lround(m_spec.durationS * 1000.0)));
    }
    m_triggerAt = m_session->now();
    m_session->forceTrigger(QStringLiteral("motion"));
    watch(r, [this](DriveReply *r) {
        if (m_aborting || !isRunning())
            return;
        if (!r->ok()) {
            const ErrorCode c = r->error().code;
            if (c == ErrorCode::NotSupported || c == ErrorCode::OutOfRange || c == ErrorCode::InvalidArgument)
                m_result.moved = false; // refused before anything was sent
            abortWith(QStringLiteral("refused"), r->error());
            return;
        }
        if (m_spec.kind == StepSpec::Kind::Position) {
            m_motionDone = true;
            waitAtRest(); // while the capture goes on: it ends once the axis is at rest
        }
    });
}

void StepTest::sendOwnStop(std::function<void(DriveReply *)> handler)
{
    m_ownStop = true;
    DriveReply *r = m_drive->stop(false);
    m_ownStop = false;
    watch(r, std::move(handler));
}

void StepTest::onStepTimer()
{
    if (m_phase != Phase::Moving || m_aborting)
        return;
    if (m_spec.kind == StepSpec::Kind::Reversal && m_segment == 0) {
        m_segment = 1;
        m_reversalAt = m_session->now() - m_triggerAt;
        m_watch.expectSpeed(-m_spec.speed, false); // it passes through rest on purpose
        watch(m_drive->jog(-m_spec.speed), [this](DriveReply *r) {
            if (!r->ok() && !m_aborting && isRunning())
                abortWith(QStringLiteral("refused"), r->error());
        });
        m_step.start(int(std::lround(m_spec.durationS * 1000.0)));
        return;
    }
    m_renew.stop();
    m_stopSent = true;
    m_watch.idle(); // our own stop: at rest is what was asked
    sendOwnStop([this](DriveReply *r) {
        if (m_aborting || !isRunning())
            return;
        m_result.stoppedBy = r->info().value(QStringLiteral("stoppedBy")).toString();
        if (!r->ok()) {
            abortWith(QStringLiteral("stop-failed"), r->error());
            return;
        }
        m_motionDone = true;
        if (m_haveCapture)
            waitAtRest();
    });
}

void StepTest::onSample(double timeS, const QMap<QString, double> &values)
{
    emit sampled(timeS, values);
    if (!isRunning())
        return;
    const double position = values.value(QStringLiteral("position"), std::nan(""));
    if (m_aborting) { // the axis stops: how far it goes is reported
        if (m_result.moved && std::isfinite(position))
            noteDistance(qint64(std::llround(position)));
        return;
    }
    if (!m_startKnown && m_phase == Phase::Arming && std::isfinite(position)) {
        m_start = qint64(std::llround(position));
        m_startKnown = true;
    }
    if (m_phase != Phase::Moving && m_phase != Phase::Stopping)
        return;
    if (m_phase == Phase::Moving) {
        const QString what = m_watch.feedSample(values);
        if (!what.isEmpty())
            return abortExternal(what);
    }
    const double speed = values.value(QStringLiteral("speed"), std::nan(""));
    if (std::isfinite(speed) && std::abs(speed) > m_limits.maxSpeed) {
        abortWith(QStringLiteral("speed-limit"),
                  {ErrorCode::Cancelled,
                   tr("The speed reached %1, above the maximum speed %2; stopped.").arg(speed).arg(m_limits.maxSpeed)});
        return;
    }
    if (!std::isfinite(position))
        return;
    const qint64 pos = qint64(std::llround(position));
    // The typical time between two samples (a running mean): how long until the next check.
    if (m_lastSampleT >= 0.0)
        m_sampleGap = m_sampleGap > 0.0 ? 0.9 * m_sampleGap + 0.1 * (timeS - m_lastSampleT) : timeS - m_lastSampleT;
    m_lastSampleT = timeS;
    // The axis' speed in counts/s, over the last few ms of captured positions.
    m_recent.append({timeS, pos});
    while (m_recent.size() > 2 && timeS - m_recent.at(1).first >= SpeedWindowS)
        m_recent.removeFirst();
    if (m_recent.size() >= 2 && timeS - m_recent.first().first > 0.0)
        m_countsPerS = double(pos - m_recent.first().second) / (timeS - m_recent.first().first);
    if (!checkTravel(pos) || !m_startKnown || m_stopSent)
        return;
    // A position step heading for its target (inside the travel: checked before) is
    // braked there by the drive's own profile; past it, it is watched as a jog is.
    if (m_spec.kind == StepSpec::Kind::Position
        && double(pos - m_start) * double(m_spec.distance) <= double(m_spec.distance) * double(m_spec.distance)
        && m_countsPerS * double(m_spec.distance) >= 0.0)
        return;
    // Trip where the axis still stops inside the limit: the stopping point — this position,
    // plus the way covered until the stop takes effect (and until the next sample) and the
    // braking at the drive's deceleration from the speed measured now — must lie within
    // the travel.
    const double reaction = StopReactionS + 2.0 * m_sampleGap;
    const double v = std::isfinite(speed) ? speed : 0.0;
    const bool accelerating = std::abs(v) < 0.98 * std::abs(double(m_spec.speed));
    const double brake = m_plan.stoppingDistance(m_countsPerS, v, reaction, accelerating, double(m_spec.speed));
    const double stopAt = double(pos - m_start) + (m_countsPerS >= 0.0 ? brake : -brake);
    if (std::abs(stopAt) > double(m_limits.maxTravel))
        abortWith(QStringLiteral("travel-limit"),
                  {ErrorCode::Cancelled,
                   tr("At %1 from the start the axis needs about %2 more to stop: it would pass the maximum travel %3; "
                      "stopped.")
                       .arg(pos - m_start)
                       .arg(std::llround(brake))
                       .arg(m_limits.maxTravel)});
}

void StepTest::noteDistance(qint64 position)
{
    m_result.endPosition = position;
    if (m_startKnown)
        m_result.farthest = std::max(m_result.farthest, qint64(std::llabs(position - m_start)));
}

bool StepTest::checkTravel(qint64 position)
{
    noteDistance(position);
    if (!m_startKnown || std::abs(double(position - m_start)) <= double(m_limits.maxTravel))
        return true;
    abortWith(QStringLiteral("travel-limit"),
              {ErrorCode::Cancelled,
               tr("The axis travelled %1 from the start, beyond the maximum travel %2; stopped.")
                   .arg(position - m_start)
                   .arg(m_limits.maxTravel)});
    return false;
}

void StepTest::onStatus(const DriveStatus &status)
{
    if (m_aborting || m_phase != Phase::Moving)
        return;
    const QString what = m_watch.feedStatus(status);
    if (!what.isEmpty())
        abortExternal(what);
}

void StepTest::abortExternal(const QString &what)
{
    m_watch.idle();
    abortWith(QStringLiteral("external-stop"),
              {ErrorCode::Cancelled,
               tr("Stopped by another master or at the drive: %1. DriveDesk sends no further "
                  "motion (no return to the start).")
                   .arg(what)});
}

void StepTest::onCaptured(const CaptureData &capture)
{
    if (!isRunning())
        return;
    m_capture = capture;
    m_haveCapture = true;
    if (m_aborting)
        return; // the aborted test's run (finish())
    if (m_restConfirmed)
        afterRest();
    else if (m_motionDone && m_phase != Phase::Stopping)
        waitAtRest();
}

void StepTest::waitAtRest()
{
    setPhase(Phase::Stopping, tr("Waiting for the axis to come to rest."));
    m_atRestPolls = 0;
    m_havePolledPosition = false;
    pollAtRest();
}

void StepTest::alarmWasTheCause(int code)
{
    m_result.abortCause = QStringLiteral("alarm");
    m_result.error = {ErrorCode::DriveException, tr("The drive raised alarm %1 during the step test.").arg(code), code};
    m_result.reason = m_result.error.message;
}

void StepTest::abortOnAlarm(int code)
{
    abortWith(QStringLiteral("alarm"),
              {ErrorCode::DriveException, tr("The drive raised alarm %1 during the step test.").arg(code), code});
}

std::optional<DriveStatus> StepTest::statusWhile(DriveReply *reply, Phase phase)
{
    if (m_aborting || m_phase != phase)
        return std::nullopt;
    if (!reply->ok()) {
        abortWith(QStringLiteral("link-lost"), reply->error());
        return std::nullopt;
    }
    const DriveStatus status = reply->status();
    if (status.alarmCode != 0) {
        abortOnAlarm(status.alarmCode);
        return std::nullopt;
    }
    return status;
}

void StepTest::pollAtRest()
{
    watch(m_drive->readStatus(), [this](DriveReply *r) {
        const std::optional<DriveStatus> status = statusWhile(r, Phase::Stopping);
        if (!status)
            return;
        const DriveStatus &s = *status;
        if (s.positionValid && !checkTravel(s.position))
            return;
        countRest(s);
        // At rest twice: the first status at rest can carry reads taken while the axis
        // still settled.
        if (m_atRestPolls >= 2) {
            if (m_spec.kind == StepSpec::Kind::Position && m_startKnown && s.positionValid) {
                const qint64 target = m_start + m_spec.distance;
                const double window = std::max(ArrivalCounts, 0.005 * std::abs(double(m_spec.distance)));
                if (std::abs(double(s.position - target)) > window)
                    return abortExternal(tr("the move came to rest at %1, %2 short of its target %3")
                                             .arg(s.position)
                                             .arg(std::llabs(target - s.position))
                                             .arg(target));
            }
            m_limit.stop();
            m_result.stopConfirmed = true;
            m_restConfirmed = true;
            if (m_haveCapture)
                return afterRest();
            // A position step's capture: settleS more after the arrival, then it ends.
            if (m_spec.recordSeconds() <= 0.0)
                QTimer::singleShot(int(std::lround(m_spec.settleS * 1000.0)), this, [this, g = m_generation] {
                    if (g == m_generation && !m_aborting && m_session && !m_haveCapture)
                        m_session->finishNow();
                });
            return; // onCaptured() goes on
        }
        QTimer::singleShot(PollMs, this, [this, g = m_generation] {
            if (g == m_generation)
                pollAtRest();
        });
    });
}

void StepTest::countRest(const DriveStatus &s)
{
    // A drive's "in position" may flicker while a disturbance trembles the shaft at rest
    // (a count either way): a running status without real movement does not start the count
    // again, a status at rest counts when the position held since the last one.
    const bool held = !s.positionValid || !m_havePolledPosition
        || std::abs(double(s.position - m_polledPosition)) <= 2.0;
    if (s.positionValid) {
        m_polledPosition = s.position;
        m_havePolledPosition = true;
    }
    if (!held)
        m_atRestPolls = 0;
    else if (!s.running)
        ++m_atRestPolls;
}

void StepTest::afterRest()
{
    buildRun();
    if (m_spec.returnToStart)
        return goBack();
    finish(StepResult::Outcome::Completed);
}

void StepTest::buildRun()
{
    TuningRun &run = m_result.run;
    run.created = QDateTime::currentDateTimeUtc();
    const DriveIdentity id = m_drive->identity();
    run.family = familyId(m_drive->family());
    run.address = m_drive->address();
    run.model = id.model;
    run.firmware = id.firmware;
    run.linkDescription = id.link;
    run.linkKind = id.link.contains(QLatin1String("can"), Qt::CaseInsensitive) ? QStringLiteral("can")
                                                                               : QStringLiteral("serial");
    run.test = StepSpec::testId(m_spec.kind);
    QJsonObject p{{QStringLiteral("speed"), m_spec.speed},
                  {QStringLiteral("maxSpeed"), m_limits.maxSpeed},
                  {QStringLiteral("maxTravel"), double(m_limits.maxTravel)},
                  {QStringLiteral("maxDuration"), m_limits.maxDurationS},
                  {QStringLiteral("startPosition"), double(m_start)},
                  {QStringLiteral("returnToStart"), m_spec.returnToStart}};
    if (m_spec.kind == StepSpec::Kind::Position)
        p.insert(QStringLiteral("distance"), double(m_spec.distance));
    else
        p.insert(QStringLiteral("duration"), m_spec.durationS);
    run.testParameters = p;
    run.settings = m_settings;
    run.capture = m_capture;
    run.units.clear();
    for (const QString &c : std::as_const(m_capture.channels)) {
        QString unit;
        for (const ChannelInfo &i : m_drive->channels())
            if (i.id == c)
                unit = i.unit;
        run.units << unit;
    }
    run.tuning = m_snapshot;
    run.outcome = QStringLiteral("completed");
    run.label = QStringLiteral("%1 %2").arg(run.test, run.created.toLocalTime().toString(QStringLiteral("HH:mm:ss")));

    StepMetrics::Input in;
    switch (m_spec.kind) {
    case StepSpec::Kind::Velocity:
        in.channel = QStringLiteral("speed");
        in.target = m_spec.speed;
        in.stepEnd = m_spec.durationS;
        run.metrics = StepMetrics::compute(m_capture, in);
        break;
    case StepSpec::Kind::Reversal: {
        // Measured on the reversal itself: from +speed (settled) to -speed.
        in.channel = QStringLiteral("speed");
        in.target = -m_spec.speed;
        in.stepEnd = m_spec.durationS;
        const double at = m_reversalAt > 0.0 ? m_reversalAt : m_spec.durationS;
        run.metrics = StepMetrics::compute(reversalPart(m_capture, at), in);
        break;
    }
    case StepSpec::Kind::Position:
        in.channel = QStringLiteral("position");
        in.target = double(m_start + m_spec.distance);
        run.metrics = StepMetrics::compute(m_capture, in);
        break;
    }
    run.metricsChannel = in.channel;
    m_result.hasRun = true;
}

void StepTest::buildAbortedRun()
{
    buildRun();
    // Not a step response: no response metric is measured on it; the peaks and the
    // sample interval stay (they are what the record holds).
    const QString why = tr("not measured: the test was aborted (%1)").arg(m_result.abortCause);
    for (const QString &key :
         {QStringLiteral("riseTime"), QStringLiteral("overshoot"), QStringLiteral("settlingTime2"),
          QStringLiteral("settlingTime5"), QStringLiteral("steadyStateError"), QStringLiteral("steadyStateRipple")})
        m_result.run.metrics.byKey(key) = Metric{std::nullopt, 0.0, why};
    m_result.run.outcome = QStringLiteral("aborted");
    m_result.run.abortCause = m_result.abortCause;
    m_result.run.abortReason = m_result.reason;
    m_result.run.label += tr(" (aborted)");
}

void StepTest::goBack()
{
    if (m_result.endPosition == m_start) {
        m_result.returnedToStart = true;
        return finish(StepResult::Outcome::Completed);
    }
    const qint64 way = m_start - m_result.endPosition;
    if (std::abs(double(way)) > double(m_limits.maxTravel)) {
        // Further than the test may go: the way back is not taken (the same limits).
        m_result.stopNote = tr("Not returning to the start position %1: it is %2 away, beyond the maximum travel %3.")
                                .arg(m_start)
                                .arg(way)
                                .arg(m_limits.maxTravel);
        return finish(StepResult::Outcome::Completed);
    }
    const qint32 speed = qint32(std::abs(m_spec.speed));
    // Announced before it starts: it is a motion like the test's own (STOP stops it).
    setPhase(
        Phase::Returning,
        tr("Returning to the start position %1: moving %2 at %3 (STOP stops it).").arg(m_start).arg(way).arg(speed));
    DriveReply *r = m_drive->hasCapability(Capability::MoveAbsolute)
        ? m_drive->moveAbsolute(m_start, speed)
        : m_drive->moveRelative(m_start - m_result.endPosition, speed);
    // The way back is as long as the way out at the test's speed: allow the test's time.
    m_limit.start(int(std::lround(m_limits.maxDurationS * 1000.0)));
    m_atRestPolls = 0;
    m_havePolledPosition = false;
    m_sawRunning = false;
    m_motionClock.start();
    watch(r, [this](DriveReply *r) {
        if (m_aborting || m_phase != Phase::Returning)
            return;
        if (!r->ok()) {
            m_result.stopNote = tr("Could not return to the start position: %1").arg(r->error().message);
            return finish(StepResult::Outcome::Completed);
        }
        pollBack();
    });
}

void StepTest::pollBack()
{
    watch(m_drive->readStatus(), [this](DriveReply *r) {
        const std::optional<DriveStatus> status = statusWhile(r, Phase::Returning);
        if (!status)
            return;
        const DriveStatus &s = *status;
        if (s.positionValid && !checkTravel(s.position))
            return;
        if (s.running)
            m_sawRunning = true;
        countRest(s);
        const bool there = s.positionValid && std::abs(double(s.position - m_start)) <= 1.0;
        if ((m_sawRunning && m_atRestPolls >= 2) || (m_atRestPolls >= 3 && (there || m_motionClock.elapsed() >= 300))) {
            m_limit.stop();
            m_result.returnedToStart = there;
            if (!there && m_sawRunning && s.positionValid && std::abs(double(s.position - m_start)) > ArrivalCounts)
                return abortExternal(tr("the return to the start came to rest at %1, %2 from the start %3")
                                         .arg(s.position)
                                         .arg(s.position - m_start)
                                         .arg(m_start));
            if (!there)
                m_result.stopNote = tr("The axis came to rest at %1, not at the start position %2.")
                                        .arg(m_result.endPosition)
                                        .arg(m_start);
            return finish(StepResult::Outcome::Completed);
        }
        QTimer::singleShot(PollMs, this, [this, g = m_generation] {
            if (g == m_generation)
                pollBack();
        });
    });
}

void StepTest::abortWith(const QString &cause, const Error &error)
{
    if (m_aborting || !isRunning())
        return;
    m_aborting = true;
    m_watch.idle();
    m_renew.stop();
    m_step.stop();
    m_limit.stop();
    // The capture goes on while the axis stops (finish() ends it): the aborted run shows
    // the motion up to its end.
    if (m_session && !m_result.moved)
        m_session->stop();
    m_result.abortCause = cause;
    m_result.error = error;
    m_result.reason = error.message;
    if (!m_result.moved) {
        // Nothing was moved: nothing to stop.
        m_result.stopConfirmed = true;
        return finish(cause == QLatin1String("refused") ? StepResult::Outcome::Failed : StepResult::Outcome::Aborted);
    }
    setPhase(Phase::Stopping, tr("Stopping the axis: %1").arg(error.message));
    if (m_linkLost) {
        m_result.stoppedBy = m_drive && m_drive->watchdogMs() > 0 ? QStringLiteral("drive-watchdog")
                                                                  : QStringLiteral("nothing");
        m_result.stopNote = !m_jogEnd.isEmpty() ? m_jogEnd
            : m_drive && m_drive->watchdogMs() > 0
            ? tr("No stop could be sent: the drive's own watchdog stops the axis; check that it has stopped.")
            : tr("No stop could be sent: the axis may still be moving; use the machine's emergency stop.");
        return finish(StepResult::Outcome::Aborted);
    }
    sendOwnStop([this](DriveReply *r) {
        m_result.stoppedBy = r->info().value(QStringLiteral("stoppedBy")).toString();
        if (!r->ok()) {
            m_result.stopNote = m_result.stoppedBy == QLatin1String("drive-watchdog")
                ? tr("STOP FAILED: %1 The drive's own watchdog stops the axis when it hears nothing from us; "
                     "check that it has stopped.")
                      .arg(r->error().message)
                : tr("STOP FAILED: %1 The axis may still be moving: use the machine's emergency stop.")
                      .arg(r->error().message);
            return finish(StepResult::Outcome::Aborted);
        }
        m_atRestPolls = 0;
        m_havePolledPosition = false;
        m_emergencySent = false;
        m_motionClock.start();
        confirmStopped();
    });
}

void StepTest::confirmStopped()
{
    watch(m_drive->readStatus(), [this](DriveReply *r) {
        if (m_phase != Phase::Stopping)
            return;
        if (!r->ok()) {
            m_result.stopNote = tr("The stop was sent, but the axis could not be seen at rest: %1")
                                    .arg(r->error().message);
            return finish(StepResult::Outcome::Aborted);
        }
        const DriveStatus s = r->status();
        if (s.positionValid)
            noteDistance(s.position);
        if (s.alarmCode != 0 && m_result.abortCause == QLatin1String("external-stop"))
            alarmWasTheCause(s.alarmCode);
        countRest(s);
        if (m_atRestPolls >= 2) {
            m_result.stopConfirmed = true;
            m_result.stopNote = tr("The axis stopped at %1 (%2 from the start; farthest %3 of the maximum travel %4).")
                                    .arg(m_result.endPosition)
                                    .arg(m_result.endPosition - m_start)
                                    .arg(m_result.farthest)
                                    .arg(m_limits.maxTravel);
            return finish(StepResult::Outcome::Aborted);
        }
        if (m_motionClock.elapsed() > StopConfirmMs) {
            if (!m_emergencySent && m_drive->hasCapability(Capability::EmergencyStop)) {
                m_emergencySent = true;
                m_motionClock.start();
                m_ownStop = true;
                DriveReply *e = m_drive->stop(true);
                m_ownStop = false;
                connect(e, &DriveReply::finished, e, &QObject::deleteLater);
            } else {
                m_result.stopNote = tr("The axis was not seen at rest %1 s after the stop: check it; use the "
                                       "machine's emergency stop if it still moves.")
                                        .arg(StopConfirmMs / 1000);
                return finish(StepResult::Outcome::Aborted);
            }
        }
        QTimer::singleShot(PollMs, this, [this, g = m_generation] {
            if (g == m_generation)
                confirmStopped();
        });
    });
}

void StepTest::finish(StepResult::Outcome outcome)
{
    m_renew.stop();
    m_step.stop();
    m_limit.stop();
    m_watch.idle();
    // An aborted test's capture up to now (onCaptured() keeps it): the run, marked aborted.
    if (m_session && m_result.moved && !m_haveCapture && m_session->state() == CaptureRecorder::State::Recording)
        m_session->finishNow();
    if (m_session)
        m_session->stop();
    m_result.outcome = outcome;
    if (outcome == StepResult::Outcome::Aborted && m_haveCapture && !m_result.hasRun)
        buildAbortedRun();
    ++m_generation; // late replies of this test are ignored
    QString line;
    switch (outcome) {
    case StepResult::Outcome::Completed: line = tr("Step test completed."); break;
    case StepResult::Outcome::Aborted: line = tr("Step test aborted: %1").arg(m_result.reason); break;
    case StepResult::Outcome::Failed: line = tr("Step test not run: %1").arg(m_result.reason); break;
    }
    setPhase(Phase::Done, line);
    emit finished(m_result);
}

} // namespace dd
