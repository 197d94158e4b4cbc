#include "core/protocol/servocan/servocan.h"

#include <QCoreApplication>

namespace dd::servocan {

namespace {

constexpr std::array<Command, 14> kCommands = {Command::Alarm,        Command::KeepAlive,    Command::Heartbeat,
                                               Command::Read,         Command::Write,        Command::RunSpeed,
                                               Command::MoveRelative, Command::MoveAbsolute, Command::PositioningSpeed,
                                               Command::Enable,       Command::Stop,         Command::StopAndDisable,
                                               Command::SetPosition,  Command::ClearAlarm};

// Names and units are registered for translation; the unit hints other than r/min (seed
// example "正 100 转") and the /100 current scale (seed: "两位小数") are not from the seed.
constexpr std::array<ReadTypeInfo, 15> kReadTypes = {{
    {ReadType::Parameter, "parameter", QT_TRANSLATE_NOOP("dd::servocan", "Parameter"), "", 1.0, 0, false},
    {ReadType::Speed, "speed", QT_TRANSLATE_NOOP("dd::servocan", "Speed"), QT_TRANSLATE_NOOP("dd::servocan", "r/min"),
     1.0, 0, false},
    {ReadType::Position, "position", QT_TRANSLATE_NOOP("dd::servocan", "Position"),
     QT_TRANSLATE_NOOP("dd::servocan", "pulses"), 1.0, 0, false},
    {ReadType::Temperature, "temperature", QT_TRANSLATE_NOOP("dd::servocan", "Temperature"), "°C", 1.0, 0, false},
    {ReadType::PositionCommand, "position-command", QT_TRANSLATE_NOOP("dd::servocan", "Position command"),
     QT_TRANSLATE_NOOP("dd::servocan", "pulses"), 1.0, 0, false},
    {ReadType::PositionError, "position-error", QT_TRANSLATE_NOOP("dd::servocan", "Position error"),
     QT_TRANSLATE_NOOP("dd::servocan", "pulses"), 1.0, 0, false},
    {ReadType::Torque, "torque", QT_TRANSLATE_NOOP("dd::servocan", "Torque"), "%", 1.0, 0, false},
    {ReadType::OutputCurrent, "output-current", QT_TRANSLATE_NOOP("dd::servocan", "Output current"), "A", 0.01, 2,
     false},
    {ReadType::SpeedCommand, "speed-command", QT_TRANSLATE_NOOP("dd::servocan", "Speed command"),
     QT_TRANSLATE_NOOP("dd::servocan", "r/min"), 1.0, 0, false},
    {ReadType::TorqueCommand, "torque-command", QT_TRANSLATE_NOOP("dd::servocan", "Torque command"), "%", 1.0, 0,
     false},
    {ReadType::RotorPosition, "rotor-position", QT_TRANSLATE_NOOP("dd::servocan", "Rotor position"), "", 1.0, 0, false},
    {ReadType::InputIo, "input-io", QT_TRANSLATE_NOOP("dd::servocan", "Input IO"), "", 1.0, 0, true},
    {ReadType::OutputIo, "output-io", QT_TRANSLATE_NOOP("dd::servocan", "Output IO"), "", 1.0, 0, true},
    {ReadType::AlarmCode, "alarm-code", QT_TRANSLATE_NOOP("dd::servocan", "Alarm code"), "", 1.0, 0, false},
    {ReadType::BusVoltage, "bus-voltage", QT_TRANSLATE_NOOP("dd::servocan", "Bus voltage"), "V", 1.0, 0, false},
}};

constexpr std::array<ReadType, 15> kReadTypeList = {
    ReadType::Parameter,       ReadType::Speed,         ReadType::Position,      ReadType::Temperature,
    ReadType::PositionCommand, ReadType::PositionError, ReadType::Torque,        ReadType::OutputCurrent,
    ReadType::SpeedCommand,    ReadType::TorqueCommand, ReadType::RotorPosition, ReadType::InputIo,
    ReadType::OutputIo,        ReadType::AlarmCode,     ReadType::BusVoltage};

quint8 byteOf(Command c)
{
    return static_cast<quint8>(c);
}
quint8 byteOf(ReadType t)
{
    return static_cast<quint8>(t);
}

CanFrameData makeFrame(quint8 station, Command command, const std::array<quint8, 5> &payload)
{
    Q_ASSERT_X(isValidStation(station), "dd::servocan", "station outside 0..99");
    CanFrameData f;
    f.id = frameId(station);
    f.extended = false;
    f.data.resize(kFrameLength);
    f.data[0] = static_cast<char>(station);
    f.data[1] = static_cast<char>(byteOf(command));
    for (int i = 0; i < 5; ++i)
        f.data[2 + i] = static_cast<char>(payload[static_cast<size_t>(i)]);
    f.data[7] = static_cast<char>(kReservedByte);
    return f;
}

// [b2][int32 LE]
std::array<quint8, 5> int32Payload(quint8 b2, qint32 value)
{
    const auto u = static_cast<quint32>(value);
    return {b2, static_cast<quint8>(u & 0xFF), static_cast<quint8>((u >> 8) & 0xFF),
            static_cast<quint8>((u >> 16) & 0xFF), static_cast<quint8>((u >> 24) & 0xFF)};
}

// [b2][index][0][int16 LE]
std::array<quint8, 5> parameterPayload(quint8 b2, quint8 index, qint16 value)
{
    Q_ASSERT_X(isValidParameterIndex(index), "dd::servocan", "parameter index outside 0..219");
    const auto u = static_cast<quint16>(value);
    return {b2, index, 0, static_cast<quint8>(u & 0xFF), static_cast<quint8>(u >> 8)};
}

QString hexByte(quint32 v, int width = 2)
{
    return QLatin1String("0x") + QString::number(v, 16).toUpper().rightJustified(width, QLatin1Char('0'));
}

} // namespace

// ---- Commands / read types ---------------------------------------------------------------

const std::array<Command, 14> &allCommands()
{
    return kCommands;
}

std::optional<Command> commandFromByte(quint8 b)
{
    for (Command c : kCommands) {
        if (byteOf(c) == b)
            return c;
    }
    return std::nullopt;
}

Direction commandDirection(Command c)
{
    switch (c) {
    case Command::Alarm:
    case Command::Heartbeat: return Direction::DriveToHost;
    case Command::Read: return Direction::Both;
    default: return Direction::HostToDrive;
    }
}

QString commandName(Command c)
{
    switch (c) {
    case Command::Alarm: return QStringLiteral("alarm");
    case Command::KeepAlive: return QStringLiteral("keep-alive");
    case Command::Heartbeat: return QStringLiteral("heartbeat");
    case Command::Read: return QStringLiteral("read");
    case Command::Write: return QStringLiteral("write");
    case Command::RunSpeed: return QStringLiteral("run-speed");
    case Command::MoveRelative: return QStringLiteral("move-relative");
    case Command::MoveAbsolute: return QStringLiteral("move-absolute");
    case Command::PositioningSpeed: return QStringLiteral("positioning-speed");
    case Command::Enable: return QStringLiteral("enable");
    case Command::Stop: return QStringLiteral("stop");
    case Command::StopAndDisable: return QStringLiteral("stop-and-disable");
    case Command::SetPosition: return QStringLiteral("set-position");
    case Command::ClearAlarm: return QStringLiteral("clear-alarm");
    }
    return QStringLiteral("unknown");
}

const std::array<ReadType, 15> &allReadTypes()
{
    return kReadTypeList;
}

std::optional<ReadType> readTypeFromByte(quint8 b)
{
    for (const ReadTypeInfo &i : kReadTypes) {
        if (byteOf(i.type) == b)
            return i.type;
    }
    return std::nullopt;
}

ReadTypeInfo readTypeInfo(ReadType t)
{
    for (const ReadTypeInfo &i : kReadTypes) {
        if (i.type == t)
            return i;
    }
    Q_UNREACHABLE();
    return kReadTypes[0];
}

double scaledValue(ReadType t, qint32 raw)
{
    return raw * readTypeInfo(t).scale;
}

// ---- Encoders ----------------------------------------------------------------------------

CanFrameData frame(quint8 station, Command command, quint8 b2, qint32 value)
{
    return makeFrame(station, command, int32Payload(b2, value));
}

CanFrameData keepAlive(quint8 station)
{
    return frame(station, Command::KeepAlive);
}

CanFrameData readParameter(quint8 station, quint8 index)
{
    return makeFrame(station, Command::Read, parameterPayload(byteOf(ReadType::Parameter), index, 0));
}

CanFrameData read(quint8 station, ReadType type)
{
    return frame(station, Command::Read, byteOf(type));
}

CanFrameData writeParameter(quint8 station, quint8 index, qint16 value)
{
    return makeFrame(station, Command::Write, parameterPayload(kWriteParameter, index, value));
}

CanFrameData runSpeed(quint8 station, qint32 speed)
{
    return frame(station, Command::RunSpeed, 0, speed);
}
CanFrameData moveRelative(quint8 station, qint32 distance)
{
    return frame(station, Command::MoveRelative, 0, distance);
}
CanFrameData moveAbsolute(quint8 station, qint32 target)
{
    return frame(station, Command::MoveAbsolute, 0, target);
}
CanFrameData positioningSpeed(quint8 station, qint32 speed)
{
    return frame(station, Command::PositioningSpeed, 0, speed);
}
CanFrameData enable(quint8 station, bool on)
{
    return frame(station, Command::Enable, on ? 1 : 0);
}
CanFrameData stop(quint8 station)
{
    return frame(station, Command::Stop);
}
CanFrameData stopAndDisable(quint8 station)
{
    return frame(station, Command::StopAndDisable);
}
CanFrameData setPosition(quint8 station, qint32 position)
{
    return frame(station, Command::SetPosition, 0, position);
}
CanFrameData clearAlarm(quint8 station)
{
    return frame(station, Command::ClearAlarm);
}

CanFrameData heartbeat(quint8 station, quint8 state, qint32 position)
{
    return frame(station, Command::Heartbeat, state, position);
}

CanFrameData alarm(quint8 station, quint16 code)
{
    return makeFrame(station, Command::Alarm,
                     {static_cast<quint8>(code & 0xFF), static_cast<quint8>(code >> 8), 0, 0, 0});
}

CanFrameData readReplyParameter(quint8 station, quint8 index, qint16 value)
{
    return makeFrame(station, Command::Read, parameterPayload(byteOf(ReadType::Parameter), index, value));
}

CanFrameData readReply(quint8 station, ReadType type, qint32 value)
{
    Q_ASSERT_X(type != ReadType::Parameter, "dd::servocan", "use readReplyParameter for 0xFA");
    return frame(station, Command::Read, byteOf(type), value);
}

// ---- Decoder -----------------------------------------------------------------------------

bool Message::isParameterFrame() const
{
    return (command == Command::Read && b2 == byteOf(ReadType::Parameter))
        || (command == Command::Write && b2 == kWriteParameter);
}

std::optional<ReadType> Message::readType() const
{
    if (command != Command::Read)
        return std::nullopt;
    return readTypeFromByte(b2);
}

Decoded<Message> decode(const CanFrameData &f)
{
    using D = Decoded<Message>;
    if (f.extended)
        return D::failure(
            QStringLiteral("servo-can: extended (29-bit) ID %1 not used by this protocol").arg(hexByte(f.id, 8)));
    if (f.id < kIdBase || f.id > kMaxId)
        return D::failure(QStringLiteral("servo-can: ID %1 outside 0x064..0x0C7").arg(hexByte(f.id, 3)));
    if (f.data.size() != kFrameLength)
        return D::failure(QStringLiteral("servo-can: DLC %1, expected 8").arg(f.data.size()));

    Message m;
    for (int i = 0; i < kFrameLength; ++i)
        m.raw[static_cast<size_t>(i)] = static_cast<quint8>(f.data[i]);

    const auto idStation = static_cast<quint8>(f.id - kIdBase);
    if (m.raw[0] != idStation)
        return D::failure(QStringLiteral("servo-can: station byte %1 does not match ID %2 (station %3)")
                              .arg(m.raw[0])
                              .arg(hexByte(f.id, 3))
                              .arg(idStation));
    const std::optional<Command> cmd = commandFromByte(m.raw[1]);
    if (!cmd)
        return D::failure(QStringLiteral("servo-can: unknown command %1").arg(hexByte(m.raw[1])));

    m.station = idStation;
    m.command = *cmd;
    m.b2 = m.raw[2];
    m.value = static_cast<qint32>(static_cast<quint32>(m.raw[3]) | (static_cast<quint32>(m.raw[4]) << 8)
                                  | (static_cast<quint32>(m.raw[5]) << 16) | (static_cast<quint32>(m.raw[6]) << 24));
    m.reservedByteOk = m.raw[7] == kReservedByte;

    if (m.command == Command::Read && !readTypeFromByte(m.b2))
        return D::failure(QStringLiteral("servo-can: unknown read type %1").arg(hexByte(m.b2)));
    if (m.command == Command::Write && m.b2 != kWriteParameter)
        return D::failure(
            QStringLiteral("servo-can: reserved write type %1 (only 0x01 is defined)").arg(hexByte(m.b2)));

    if (m.isParameterFrame()) {
        if (!isValidParameterIndex(m.raw[3]))
            return D::failure(QStringLiteral("servo-can: parameter index %1 outside 0..219").arg(m.raw[3]));
        m.paramIndex = m.raw[3];
        m.paramValue = static_cast<qint16>(static_cast<quint16>(m.raw[5] | (m.raw[6] << 8)));
    }
    return D::success(m);
}

bool isReplyTo(const Message &received, quint8 station, ReadType type, quint8 paramIndex)
{
    if (received.command != Command::Read || received.station != station || received.b2 != byteOf(type))
        return false;
    return type != ReadType::Parameter || received.paramIndex == paramIndex;
}

bool isReplyTo(const Message &received, const Message &request)
{
    const std::optional<ReadType> type = request.readType();
    if (!type)
        return false;
    return isReplyTo(received, request.station, *type, request.paramIndex);
}

} // namespace dd::servocan
