#include "sim/servocan/simservocandrive.h"

#include <QJsonArray>

#include <cmath>
#include <limits>

namespace dd {

namespace sc = servocan;
using sc::Command;
using sc::ReadType;

namespace {

constexpr qint64 kHeartbeatUs = std::chrono::microseconds(sc::kHeartbeatPeriod).count();
constexpr qint64 kAlarmRepeatUs = std::chrono::microseconds(sc::kAlarmRepeat).count();
constexpr qint64 kWatchdogUs = std::chrono::microseconds(sc::kWatchdog).count();

qint32 clampToInt32(double v)
{
    if (!(v == v))
        return 0;
    const double r = std::round(v);
    if (r >= double(std::numeric_limits<qint32>::max()))
        return std::numeric_limits<qint32>::max();
    if (r <= double(std::numeric_limits<qint32>::min()))
        return std::numeric_limits<qint32>::min();
    return static_cast<qint32>(r);
}

} // namespace

SimServoCanDrive::SimServoCanDrive(int station, const MotorModel::Config &motor)
    : m_station(sc::isValidStation(station) ? station : 1)
    , m_params(defaultParameters(m_station))
    , m_motor(MotorModel::closedLoopConfig(motor))
{
    applyLoopGainParameters(
        loopGainParameters(), [this](int i) { return qint64(parameter(i)); }, &m_motor);
}

const QList<LoopGainParameter> &SimServoCanDrive::loopGainParameters()
{
    using R = LoopGainParameter::Role;
    static const QList<LoopGainParameter> table = {
        {60, R::SpeedKp, 30, 1, 1000},      {61, R::SpeedKi, 30, 0, 5000},
        {62, R::PositionKp, 60, 0, 1000},   {63, R::SpeedFeedforward, 100, 0, 100},
        {64, R::Acceleration, 6, 1, 32767}, {65, R::TorqueFeedforward, 100, 0, 100},
    };
    return table;
}

SimServoCanDrive::Parameters SimServoCanDrive::defaultParameters(int station)
{
    Parameters p{};
    for (int i = 0; i < sc::kParameterCount; ++i)
        p[static_cast<size_t>(i)] = static_cast<qint16>((i * 37 + 11) % 4000 - 1000);
    for (const LoopGainParameter &g : loopGainParameters())
        p[static_cast<size_t>(g.index)] = static_cast<qint16>(g.defaultValue);
    p[sc::kParamControlMode] = 8;
    p[sc::kParamCommMode] = 1;
    p[sc::kParamStation] = static_cast<qint16>(station);
    return p;
}

QString SimServoCanDrive::describe() const
{
    return QStringLiteral("servo-can station %1").arg(m_station);
}

qint16 SimServoCanDrive::parameter(int index) const
{
    return sc::isValidParameterIndex(index) ? m_params[static_cast<size_t>(index)] : 0;
}

void SimServoCanDrive::setParameter(int index, qint16 value)
{
    if (sc::isValidParameterIndex(index))
        m_params[static_cast<size_t>(index)] = value;
}

bool SimServoCanDrive::canMode() const
{
    return m_params[sc::kParamCommMode] == 1 && m_params[sc::kParamControlMode] == 8;
}

bool SimServoCanDrive::heartbeatsOn() const
{
    return m_params[sc::kParamCommMode] == 1;
}

double SimServoCanDrive::rpmToCounts(qint32 rpm) const
{
    return double(rpm) * countsPerRev() / 60.0;
}

qint32 SimServoCanDrive::countsToRpm(double countsPerSecond) const
{
    return clampToInt32(countsPerSecond * 60.0 / countsPerRev());
}

void SimServoCanDrive::setWriteProtected(int index, bool on)
{
    if (sc::isValidParameterIndex(index))
        m_writeProtected[static_cast<size_t>(index)] = on;
}

void SimServoCanDrive::restart()
{
    const int p75 = m_params[sc::kParamStation];
    if (sc::isValidStation(p75))
        m_station = p75;
    m_motor.stop();
    m_motor.emergencyStop();
    m_motor.disable();
    m_positioningSpeed = 0;
    m_disableAtRest = false;
    m_watchdogDeadlineUs = -1;
    m_hostOnline = false;
    m_lastKeepAliveUs = -1;
    m_nextHeartbeatUs = m_nowUs;
}

void SimServoCanDrive::injectAlarm(int code)
{
    if (code == 0)
        m_motor.clearAlarm(); // the cause gone and reset, as SimBench::injectAlarm(…, 0) promises
    else
        m_motor.injectAlarm(code);
}

void SimServoCanDrive::advanceTo(qint64 nowUs)
{
    if (nowUs < m_nowUs)
        return;
    m_nowUs = nowUs;
    applyLoopGainParameters(
        loopGainParameters(), [this](int i) { return qint64(parameter(i)); }, &m_motor);
    m_motor.advanceTo(double(nowUs) / 1e6);
    if (m_disableAtRest && !m_motor.isMoving()) {
        m_motor.disable();
        m_disableAtRest = false;
    }
}

// ---- Host frames ----------------------------------------------------------------------------

QList<CanFrameData> SimServoCanDrive::onCanFrame(const CanFrameData &frame, qint64 nowUs)
{
    if (frame.extended || frame.id != sc::frameId(static_cast<quint8>(m_station)))
        return {};
    const Decoded<sc::Message> d = sc::decode(frame);
    if (!d.ok())
        return {}; // a real drive ignores what it does not understand
    const sc::Message &m = *d.value;
    if (!m.reservedByteOk)
        return {}; // DATE[7] "目前需固定的填入 0xff": a frame without it is not taken
    if (sc::commandDirection(m.command) == sc::Direction::DriveToHost)
        return {}; // another drive's frame on our ID (a misconfigured bus): not for us
    ++m_stats.framesForUs;
    switch (m.command) {
    case Command::Read: return answerRead(m);
    case Command::Write: handleWrite(m); return {};
    case Command::KeepAlive:
        ++m_stats.keepAlives;
        m_lastKeepAliveUs = nowUs;
        m_watchdogDeadlineUs = nowUs + kWatchdogUs;
        m_hostOnline = true;
        return {};
    case Command::ClearAlarm: m_motor.clearAlarm(); return {};
    default: handleMotion(m, nowUs); return {};
    }
}

QList<CanFrameData> SimServoCanDrive::answerRead(const sc::Message &m)
{
    const std::optional<ReadType> type = m.readType();
    if (!type)
        return {};
    ++m_stats.readsAnswered;
    const quint8 st = static_cast<quint8>(m_station);
    if (*type == ReadType::Parameter)
        return {sc::readReplyParameter(st, m.paramIndex, m_params[m.paramIndex])};
    const MotorModel &mm = m_motor;
    qint32 v = 0;
    switch (*type) {
    case ReadType::Parameter: break;
    case ReadType::Speed: v = countsToRpm(mm.speed()); break;
    case ReadType::Position: v = clampToInt32(double(mm.position())); break;
    case ReadType::Temperature: v = clampToInt32(mm.temperature()); break;
    case ReadType::PositionCommand: v = clampToInt32(double(mm.commandPosition())); break;
    case ReadType::PositionError: v = clampToInt32(double(mm.positionError())); break;
    case ReadType::Torque: v = clampToInt32(mm.torquePercent()); break;
    case ReadType::OutputCurrent: v = clampToInt32(mm.current() * 100.0); break;
    case ReadType::SpeedCommand: v = countsToRpm(mm.targetSpeed()); break;
    case ReadType::TorqueCommand: v = clampToInt32(mm.torquePercent() - mm.noiseSample(16) * 0.5); break;
    case ReadType::RotorPosition: {
        const qint64 cpr = std::max<qint64>(1, qint64(std::llround(countsPerRev())));
        v = static_cast<qint32>(((mm.position() % cpr) + cpr) % cpr);
        break;
    }
    case ReadType::InputIo: v = static_cast<qint32>(m_inputs); break;
    case ReadType::OutputIo: v = outputs(); break;
    case ReadType::AlarmCode: v = mm.alarmCode(); break;
    case ReadType::BusVoltage: v = clampToInt32(mm.busVoltage()); break;
    }
    return {sc::readReply(st, *type, v)};
}

qint32 SimServoCanDrive::outputs() const
{
    qint32 bits = 0;
    if (m_motor.alarmCode() == 0)
        bits |= 1;
    if (m_motor.isEnabled())
        bits |= 2;
    if (m_motor.alarmCode() != 0)
        bits |= 4;
    if (!m_motor.isMoving())
        bits |= 8;
    return bits;
}

void SimServoCanDrive::handleWrite(const sc::Message &m)
{
    // The decoder guarantees sub-code 0x01 and index 0..219.
    if (m_writeProtected[m.paramIndex] || (m.paramIndex == sc::kParamStation && !sc::isValidStation(m.paramValue))) {
        ++m_stats.writesRefused;
        return;
    }
    ++m_stats.parameterWrites;
    m_stats.writtenIndexes.insert(m.paramIndex);
    m_params[m.paramIndex] = m.paramValue;
}

void SimServoCanDrive::handleMotion(const sc::Message &m, qint64 nowUs)
{
    if (!canMode()) {
        ++m_stats.commandsIgnored;
        return;
    }
    ++m_stats.motionCommands;
    const bool starts = m.command == Command::RunSpeed || m.command == Command::MoveRelative
        || m.command == Command::MoveAbsolute;
    if (starts && (m_watchdogDeadlineUs < 0 || m_watchdogDeadlineUs < nowUs))
        m_watchdogDeadlineUs = nowUs + kWatchdogUs; // a host without keep-alive gets 2 s
    if (starts || m.command == Command::Enable || m.command == Command::Stop)
        m_disableAtRest = false;
    switch (m.command) {
    case Command::RunSpeed:
        if (m_motor.enable())
            m_motor.runSpeed(rpmToCounts(m.value));
        break;
    case Command::MoveRelative:
    case Command::MoveAbsolute: {
        if (!m_motor.enable() || m_positioningSpeed == 0)
            break; // positioning speed 0: enabled, no motion (seed)
        const double speed = std::abs(rpmToCounts(m_positioningSpeed));
        if (m.command == Command::MoveRelative)
            m_motor.moveRelative(m.value, speed);
        else
            m_motor.moveAbsolute(m.value, speed);
        break;
    }
    case Command::PositioningSpeed:
        m_positioningSpeed = m.value;
        if (m_motor.mode() == MotorModel::Mode::Position && m.value != 0)
            m_motor.setMoveSpeed(std::abs(rpmToCounts(m.value)));
        break;
    case Command::Enable:
        if (m.enableOn())
            m_motor.enable();
        else
            m_motor.disable();
        break;
    case Command::Stop: m_motor.stop(); break;
    case Command::StopAndDisable:
        m_motor.stop();
        m_disableAtRest = true;
        if (!m_motor.isMoving()) {
            m_motor.disable();
            m_disableAtRest = false;
        }
        break;
    case Command::SetPosition: m_motor.setPosition(m.value); break;
    default: break;
    }
}

// ---- Periodic frames ------------------------------------------------------------------------

QList<CanFrameData> SimServoCanDrive::tick(qint64 nowUs)
{
    QList<CanFrameData> out;
    const quint8 st = static_cast<quint8>(m_station);

    // Keep-alive watchdog: stop, stay enabled (hold the shaft).
    if (m_watchdogDeadlineUs >= 0 && nowUs >= m_watchdogDeadlineUs) {
        m_watchdogDeadlineUs = -1;
        const bool wasOnline = m_hostOnline;
        m_hostOnline = false;
        if (m_motor.isMoving() || wasOnline) {
            ++m_stats.watchdogTrips;
            if (m_motor.isMoving())
                m_motor.stop();
        }
    }

    // Alarm frames: at once on a change, every 2 s while alarmed.
    const int alarm = m_motor.alarmCode();
    if (alarm != m_reportedAlarm) {
        m_reportedAlarm = alarm;
        out.append(sc::alarm(st, static_cast<quint16>(alarm)));
        ++m_stats.alarmFramesSent;
        m_nextAlarmRepeatUs = alarm != 0 ? nowUs + kAlarmRepeatUs : -1;
    } else if (alarm != 0 && m_nextAlarmRepeatUs >= 0 && nowUs >= m_nextAlarmRepeatUs) {
        out.append(sc::alarm(st, static_cast<quint16>(alarm)));
        ++m_stats.alarmFramesSent;
        while (m_nextAlarmRepeatUs <= nowUs)
            m_nextAlarmRepeatUs += kAlarmRepeatUs;
    }

    // Heartbeat every 30 ms (when P74 = 1), on its own cadence.
    if (heartbeatsOn() && nowUs >= m_nextHeartbeatUs) {
        const quint8 state = m_motor.isMoving() ? 0x00 : sc::kHeartbeatIdle;
        out.append(sc::heartbeat(st, state, clampToInt32(double(m_motor.position()))));
        ++m_stats.heartbeatsSent;
        m_nextHeartbeatUs += kHeartbeatUs;
        if (m_nextHeartbeatUs <= nowUs) // a long stall: no burst of late heartbeats
            m_nextHeartbeatUs = nowUs + kHeartbeatUs;
    }
    return out;
}

// ---- State ------------------------------------------------------------------------------------

QJsonObject SimServoCanDrive::saveState() const
{
    QJsonArray params;
    for (qint16 v : m_params)
        params.append(int(v));
    QJsonObject o;
    o.insert(QStringLiteral("family"), QStringLiteral("servo-can"));
    o.insert(QStringLiteral("station"), m_station);
    o.insert(QStringLiteral("parameters"), params);
    o.insert(QStringLiteral("position"), double(m_motor.position()));
    o.insert(QStringLiteral("alarm"), m_motor.alarmCode());
    return o;
}

bool SimServoCanDrive::loadState(const QJsonObject &state, QString *error)
{
    auto fail = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (state.contains(QStringLiteral("family"))
        && state.value(QStringLiteral("family")).toString() != QLatin1String("servo-can"))
        return fail(QStringLiteral("state is for family \"%1\", not servo-can")
                        .arg(state.value(QStringLiteral("family")).toString()));
    const QJsonArray arr = state.value(QStringLiteral("parameters")).toArray();
    if (arr.size() != sc::kParameterCount)
        return fail(
            QStringLiteral("\"parameters\" must hold %1 values, found %2").arg(sc::kParameterCount).arg(arr.size()));
    Parameters p{};
    for (int i = 0; i < arr.size(); ++i) {
        const QJsonValue v = arr.at(i);
        const double d = v.toDouble(std::nan(""));
        if (!v.isDouble() || d != std::floor(d) || d < std::numeric_limits<qint16>::min()
            || d > std::numeric_limits<qint16>::max())
            return fail(QStringLiteral("parameter %1 is not a 16-bit integer").arg(i));
        p[static_cast<size_t>(i)] = static_cast<qint16>(d);
    }
    int station = m_station;
    if (state.contains(QStringLiteral("station"))) {
        station = state.value(QStringLiteral("station")).toInt(-1);
        if (!sc::isValidStation(station))
            return fail(QStringLiteral("\"station\" must be 0..99"));
    }
    const double pos = state.value(QStringLiteral("position")).toDouble(0.0);
    if (pos != std::floor(pos) || std::abs(pos) > double(std::numeric_limits<qint32>::max()))
        return fail(QStringLiteral("\"position\" must be a 32-bit integer"));
    const int alarm = state.value(QStringLiteral("alarm")).toInt(0);
    if (alarm < 0 || alarm > 0xFFFF)
        return fail(QStringLiteral("\"alarm\" must be 0..65535"));

    m_params = p;
    m_station = station;
    m_motor.setPosition(static_cast<qint64>(pos));
    if (alarm != 0)
        m_motor.injectAlarm(alarm);
    else
        m_motor.clearAlarm();
    return true;
}

std::unique_ptr<SimCanDevice> SimServoCanDrive::create(const SimDeviceSpec &spec, Error *)
{
    return std::make_unique<SimServoCanDrive>(spec.address,
                                              MotorModel::closedLoopConfig(MotorModel::Config(), spec.resonanceHz));
}

} // namespace dd
