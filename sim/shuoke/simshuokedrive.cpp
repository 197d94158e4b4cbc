#include "sim/shuoke/simshuokedrive.h"

#include <algorithm>
#include <cmath>

namespace dd {

using namespace shuoke;

namespace {
constexpr int kMaxRecordedRequests = 4096;
constexpr qint64 kMaxPulses31 = 0x7FFFFFFF; // "31位"
} // namespace

SimShuokeDrive::SimShuokeDrive()
    : SimShuokeDrive(Config{})
{
}

SimShuokeDrive::SimShuokeDrive(const Config &config)
    : m_config(config)
    , m_axis(config.model == Model::M6505)
{
    m_axis.setSwitches(config.switches);
    m_axis.setPowered(config.enableInput);
    resetSettings();
}

void SimShuokeDrive::setEnableInput(bool on)
{
    m_config.enableInput = on;
    m_axis.setPowered(on);
}

QString SimShuokeDrive::mediumName(Medium medium)
{
    switch (medium) {
    case Medium::Serial: return QStringLiteral("serial");
    case Medium::Can: return QStringLiteral("can");
    case Medium::Plc: return QStringLiteral("plc");
    }
    return QString();
}

void SimShuokeDrive::resetSettings()
{
    m_settings.clear();
    m_settings.insert(CmdSetBaudCode, m_config.baudCode);
    m_settings.insert(CmdSetStartSpeed, 500);
    m_settings.insert(CmdSetMaxSpeed, 10000);
    m_settings.insert(CmdSetStopSpeed, 500);
    m_settings.insert(CmdSetAcceleration, 50000);
    m_settings.insert(CmdSetDeceleration, 50000);
    m_settings.insert(CmdSetHomingSpeed, 5000);
    m_settings.insert(CmdSetPlcBase, m_config.plcBase);
    m_settings.insert(CmdSetSpeedStep, 100);
    m_settings.insert(CmdSkipCrcCheck, 0);
    m_settings.insert(CmdFixedLengthReplies, 0);
    m_settings.insert(CmdCanFrameFormat, m_config.canExtended ? 1 : 0);
    m_settings.insert(CmdCanBitrate, m_config.canBitrateCode);
    m_settings.insert(CmdEncoderDirection, 0);
    m_settings.insert(CmdMotionDirection, 0);
    m_settings.insert(CmdErrorCorrection, 0);
    m_settings.insert(CmdSetGearNumerator, 1);
    m_settings.insert(CmdSetGearDenominator, 1);
    m_settings.insert(CmdEncoderAbTolerance, 200);
    m_settings.insert(CmdNoEncoderMaxPulses, 5000);
    m_ioSubstitution.clear();
    applySettingsToAxis();
}

void SimShuokeDrive::setSetting(quint8 setCommand, qint64 value)
{
    m_settings.insert(setCommand, value);
    if (setCommand == CmdSetBaudCode)
        m_config.baudCode = static_cast<int>(value);
    if (setCommand == CmdSetPlcBase)
        m_config.plcBase = static_cast<quint16>(value);
    applySettingsToAxis();
}

void SimShuokeDrive::applySettingsToAxis()
{
    m_axis.setAcceleration(static_cast<double>(m_settings.value(CmdSetAcceleration)));
    m_axis.setDeceleration(static_cast<double>(m_settings.value(CmdSetDeceleration)));
}

bool SimShuokeDrive::isBroadcast(quint8 address) const
{
    return m_config.broadcasts.contains(address);
}

bool SimShuokeDrive::isAddressed(quint8 address) const
{
    return address == m_config.address || isBroadcast(address);
}

void SimShuokeDrive::advanceTo(qint64 nowUs)
{
    if (nowUs > m_nowUs)
        m_nowUs = nowUs;
    m_axis.advanceTo(nowUs);
}

void SimShuokeDrive::powerCycle(qint64 nowUs)
{
    advanceTo(nowUs);
    m_axis.emergencyStop();
    if (m_pendingFactoryReset) {
        m_config.baudCode = 6;
        m_config.canBitrateCode = kDefaultCanBitrateCode;
        m_config.canExtended = false;
        resetSettings();
        m_pendingFactoryReset = false;
    }
    if (m_pendingAddress)
        m_config.address = *m_pendingAddress;
    if (m_pendingCanBitrate)
        m_config.canBitrateCode = *m_pendingCanBitrate;
    if (m_pendingCanExtended)
        m_config.canExtended = *m_pendingCanExtended;
    m_pendingAddress.reset();
    m_pendingCanBitrate.reset();
    m_pendingCanExtended.reset();
    m_powerOnUs = nowUs;
}

int SimShuokeDrive::serialBaud(qint64 nowUs) const
{
    if (m_config.powerUpWindowMs > 0 && nowUs - m_powerOnUs < qint64(m_config.powerUpWindowMs) * 1000)
        return 9600;
    const int baud = baudRateForCode(m_config.baudCode);
    return baud > 0 ? baud : 9600;
}

Frame SimShuokeDrive::failure(quint8 command, quint8 code) const
{
    return Frame::failureReply(m_config.address, command, code);
}

QByteArray SimShuokeDrive::u32(qint64 v) const
{
    return encodeUInt32(static_cast<quint32>(v), m_config.byteOrder);
}

QByteArray SimShuokeDrive::i32(qint64 v) const
{
    return encodeInt32(static_cast<qint32>(v), m_config.byteOrder);
}

qint32 SimShuokeDrive::dataInt(const QByteArray &data) const
{
    return decodeInt32(data, m_config.byteOrder).value_or(0);
}

quint32 SimShuokeDrive::dataUInt(const QByteArray &data) const
{
    return decodeUInt32(data, m_config.byteOrder).value_or(0);
}

std::optional<Frame> SimShuokeDrive::handle(const Frame &request, Medium medium, qint64 nowUs)
{
    advanceTo(nowUs);
    if (request.failure || !isAddressed(request.address))
        return std::nullopt;
    if (medium != Medium::Can && m_config.minCommandGapMs > 0) {
        const bool tooSoon = m_lastSerialRequestUs >= 0
            && nowUs - m_lastSerialRequestUs < qint64(m_config.minCommandGapMs) * 1000;
        m_lastSerialRequestUs = nowUs;
        if (tooSoon) {
            ++m_tooSoon;
            return std::nullopt; // still busy with the previous command
        }
    }
    ++m_requestCount;
    if (m_requestTimes.size() >= kMaxRecordedRequests) {
        m_requestTimes.removeFirst();
        m_requestCommands.removeFirst();
    }
    m_requestTimes.append(nowUs);
    m_requestCommands.append(request.command);

    const bool broadcast = isBroadcast(request.address);
    const quint8 cmd = request.command;
    const int len = static_cast<int>(request.data.size());
    const CommandInfo *info = commandInfo(cmd);
    auto refuse = [&](quint8 code) -> std::optional<Frame> {
        if (broadcast && code != FailureNoBroadcast)
            return std::nullopt; // nothing useful can answer a broadcast
        return failure(cmd, code);
    };
    if (!info)
        return refuse(FailureUnknownCommand);
    if (broadcast && !info->flags.testFlag(BroadcastAllowed))
        return refuse(FailureNoBroadcast);
    if (!info->allowsRequestLength(len))
        return refuse(FailureTimeoutOrLength);
    const bool overCan = medium == Medium::Can;
    if (!isSupportedBy(cmd, m_config.model, len) || (overCan && info->flags.testFlag(SerialOnly))
        || (!overCan && info->flags.testFlag(CanOnly)))
        return refuse(FailureUnknownCommand);
    // Gear numerator / denominator (0x5F / 0x61): "大于16位，只取16无符号位数" — the drive
    // keeps the low 16 bits of a larger value (the client refuses to send one).
    const QByteArray checked = cmd == CmdSetGearNumerator || cmd == CmdSetGearDenominator
        ? encodeUInt32(dataUInt(request.data) & 0xFFFFu, m_config.byteOrder)
        : request.data;
    if (!validateRequestData(cmd, checked, m_config.byteOrder).isEmpty())
        return refuse(FailureOutOfRange);

    std::optional<Frame> reply = execute(request, medium);
    if (broadcast && cmd != CmdQueryAddress)
        return std::nullopt;
    // The reply command the seed prints: 0x41 for 0x42..0x46, 0x3E for the homing forms of
    // 0x4E / 0x4F (1 data byte); every other command answers with its own code.
    if (reply && !reply->failure && info->replyCommands[1] != 0
        && (len == 1 || (cmd != CmdHomeOrSCurveInt32 && cmd != CmdHomeOrSCurveDirection24)))
        reply->command = info->replyCommands[1];
    return reply;
}

std::optional<Frame> SimShuokeDrive::execute(const Frame &request, Medium medium)
{
    Q_UNUSED(medium);
    const quint8 cmd = request.command;
    const QByteArray &data = request.data;
    auto ok = [this, cmd](const QByteArray &replyData = {}) { return Frame::make(m_config.address, cmd, replyData); };
    const quint8 byte0 = data.isEmpty() ? 0 : static_cast<quint8>(data.at(0));

    switch (cmd) {
    case CmdHandshake:
    case CmdQueryAddress: return ok();
    // The seed's worked example (ASCII and CAN chapters: 发送 01 22 01 02, 应答 02 22 01 02)
    // answers from the new address; the drive listens on the old one until it restarts.
    case CmdChangeAddress: m_pendingAddress = byte0; return Frame::make(byte0, cmd, data);
    case CmdGetBaudCode: return ok(QByteArray(1, static_cast<char>(m_config.baudCode)));
    case CmdSetBaudCode:
        setSetting(CmdSetBaudCode, byte0); // the new rate applies to the next request
        return ok(data);
    // Gear numerator / denominator: the low 16 bits (大于16位，只取16无符号位数).
    case CmdSetGearNumerator:
    case CmdSetGearDenominator: setSetting(cmd, dataUInt(data) & 0xFFFFu); return ok();
    case CmdSetStartSpeed:
    case CmdSetMaxSpeed:
    case CmdSetStopSpeed:
    case CmdSetAcceleration:
    case CmdSetDeceleration:
    case CmdSetHomingSpeed:
    case CmdSetSpeedStep:
    case CmdEncoderAbTolerance:
    case CmdNoEncoderMaxPulses: setSetting(cmd, dataUInt(data)); return ok();
    case CmdGetStartSpeed:
    case CmdGetMaxSpeed:
    case CmdGetStopSpeed:
    case CmdGetAcceleration:
    case CmdGetDeceleration:
    case CmdGetHomingSpeed:
    case CmdGetGearNumerator:
    case CmdGetGearDenominator: return ok(u32(m_settings.value(static_cast<quint8>(cmd - 1))));
    case CmdEncoderDirection:
    case CmdMotionDirection:
    case CmdErrorCorrection: setSetting(cmd, byte0); return ok();
    case CmdSkipCrcCheck:
    case CmdFixedLengthReplies: setSetting(cmd, byte0); return ok(data);
    case CmdCanFrameFormat:
        setSetting(cmd, byte0);
        m_pendingCanExtended = byte0 != 0;
        return ok(data);
    case CmdCanBitrate:
        setSetting(cmd, byte0);
        m_pendingCanBitrate = byte0;
        return ok(data);
    case CmdSetPlcBase: setSetting(cmd, decodeUInt16(data, m_config.byteOrder).value_or(0)); return ok();
    case CmdSetIoSubstitution: m_ioSubstitution.insert(byte0, data); return ok();
    case CmdReadIoSubstitution: {
        const QByteArray entry = m_ioSubstitution.value(byte0);
        return ok(entry.isEmpty() ? QByteArray(1, static_cast<char>(byte0)) : entry);
    }
    case CmdReadInputs:
    case CmdReadOtherInputs: {
        quint8 bits = cmd == CmdReadInputs ? m_config.inputs : m_config.controlInputs;
        if (cmd == CmdReadOtherInputs)
            bits = static_cast<quint8>((bits & ~0x04) | (m_config.enableInput ? 0x04 : 0));
        QByteArray out;
        for (int i = 0; i < 5; ++i)
            out.append(static_cast<char>((bits >> i) & 1));
        return ok(out);
    }
    case CmdFactoryReset: m_pendingFactoryReset = true; return ok();
    case CmdSerialToCanEcho:
    case CmdCanToSerialEcho: return ok(data);
    case CmdClosedLoopGetAbsolute: return ok(i32(m_axis.closedLoopAbsolute()));
    case CmdClosedLoopGetRelative: return ok(i32(m_axis.closedLoopRelative()));
    case CmdClosedLoopSetAbsolute: m_axis.setClosedLoopAbsolute(data.isEmpty() ? 0 : dataInt(data)); return ok();
    case CmdClosedLoopSetRelative: m_axis.setClosedLoopRelative(data.isEmpty() ? 0 : dataInt(data)); return ok();
    default: break;
    }
    return executeMotion(request);
}

std::optional<Frame> SimShuokeDrive::executeMotion(const Frame &request)
{
    const quint8 cmd = request.command;
    const QByteArray &data = request.data;
    const Frame done = Frame::make(m_config.address, cmd);
    const double maxSpeed = static_cast<double>(m_settings.value(CmdSetMaxSpeed));
    const double homing = static_cast<double>(m_settings.value(CmdSetHomingSpeed));
    switch (cmd) {
    case CmdMoveRelative:
    case CmdClosedLoopMove: m_axis.moveRelative(dataInt(data), maxSpeed); return done;
    case CmdMoveRelativeDirection24:
        m_axis.moveRelative(decodeDirection24(data, m_config.byteOrder).value_or(0), maxSpeed);
        return done;
    case CmdClosedLoopGearedMove: {
        // 实际反馈脉冲数 = 设定反馈脉冲数 * 齿轮分子 / 齿轮分母; 最高支持 … 31位: a product
        // beyond 31 bits is out of range (0x04).
        const qint64 num = m_settings.value(CmdSetGearNumerator);
        const qint64 den = std::max<qint64>(1, m_settings.value(CmdSetGearDenominator));
        const qint64 pulses = qint64(dataInt(data)) * num / den;
        if (pulses > kMaxPulses31 || pulses < -kMaxPulses31)
            return failure(cmd, FailureOutOfRange);
        m_axis.moveRelative(pulses, maxSpeed);
        return done;
    }
    case CmdClosedLoopMoveAbsolute: {
        // 计算后的实际运动距离最大为31位数据: the distance to the target fits 31 bits.
        const qint64 target = m_axis.motorPositionForClosedLoop(dataInt(data));
        const qint64 distance = target - m_axis.motorPosition();
        if (distance > kMaxPulses31 || distance < -kMaxPulses31)
            return failure(cmd, FailureOutOfRange);
        m_axis.moveToMotorPosition(target, maxSpeed);
        return done;
    }
    case CmdRunSpeed: m_axis.runSpeed(dataInt(data)); return done;
    case CmdRunSpeedDirection24: m_axis.runSpeed(decodeDirection24(data, m_config.byteOrder).value_or(0)); return done;
    case CmdChangeSpeed: m_axis.changeSpeed(dataUInt(data)); return done;
    case CmdSpeedStepUp:
    case CmdSpeedStepDown: {
        // 运动中定量改变速度: 运动速度 = 当前运动速度 ± F, during motion only: a jog keeps
        // its direction, a move its target; at rest nothing starts.
        if (!m_axis.isRunning() || m_axis.isHoming())
            return done;
        const double step = static_cast<double>(m_settings.value(CmdSetSpeedStep));
        const double magnitude = m_axis.cruiseSpeed() + (cmd == CmdSpeedStepUp ? step : -step);
        m_axis.changeSpeed(std::clamp(magnitude, 0.0, static_cast<double>(kMaxSpeed)));
        return done;
    }
    // "4BYTE 运动速度": the magnitude; only the position (0x37) is signed.
    case CmdQuerySpeed: return Frame::make(m_config.address, cmd, u32(std::llround(std::abs(m_axis.speed()))));
    case CmdQueryAbsolutePosition: return Frame::make(m_config.address, cmd, i32(m_axis.absolutePosition()));
    case CmdClearAbsolutePosition: m_axis.clearAbsolute(); return done;
    case CmdQueryRelativePosition: return Frame::make(m_config.address, cmd, i32(m_axis.relativePosition()));
    case CmdClearRelativePosition: m_axis.clearRelative(); return done;
    case CmdQueryStatus: {
        MotionStatus s;
        s.running = m_axis.isRunning();
        s.leftLimit = m_axis.leftLimit();
        s.origin = m_axis.origin();
        s.rightLimit = m_axis.rightLimit();
        s.enableInput = m_config.enableInput;
        return Frame::make(m_config.address, cmd, encodeMotionStatus(s));
    }
    case CmdEmergencyStop: m_axis.emergencyStop(); return done;
    case CmdDecelerateStop: m_axis.stop(); return done;
    case CmdHome: m_axis.startHoming(static_cast<quint8>(data.at(0)) == 1, homing); return done;
    case CmdHomeOrSCurveInt32:
    case CmdHomeOrSCurveDirection24:
        if (data.size() == 1) {
            // 0x4E: 先到限位，然后反方向查找 (limit first, then back to the origin), zeroes;
            // 0x4F: as 0x3E but without 自动将相对位置和绝对位置清零 (no zeroing).
            m_axis.startHoming(static_cast<quint8>(data.at(0)) == 1, homing,
                               cmd == CmdHomeOrSCurveInt32 ? SimShuokeAxis::Homing::LimitFirst
                                                           : SimShuokeAxis::Homing::KeepCounters);
        } else {
            const qint64 distance = cmd == CmdHomeOrSCurveInt32
                ? dataInt(data)
                : decodeDirection24(data, m_config.byteOrder).value_or(0);
            m_axis.moveRelative(distance, maxSpeed);
        }
        return done;
    default: break;
    }
    return failure(cmd, FailureUnknownCommand);
}

} // namespace dd
