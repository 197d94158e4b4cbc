#pragma once

#include "core/protocol/canframedata.h"
#include "core/protocol/codecresult.h"

#include <QString>
#include <QtGlobal>

#include <array>
#include <chrono>
#include <optional>

// Pure codec of the `servo-can` family (docs/protocols/servo-can.md): CAN 2.0A, 1 Mbit/s,
// frame ID = 0x64 + station in both directions, DLC 8,
// data = [station][command][b2][b3][b4][b5][b6][0xFF], int32 payloads little-endian in b3..b6.
// Both directions are encoded: the host side for the link, the drive side for the simulator.
namespace dd::servocan {

// ---- Constants ---------------------------------------------------------------------------
constexpr quint32 kIdBase = 0x64;  // frame ID = kIdBase + station
constexpr quint8 kMaxStation = 99; // stations 0..99
constexpr int kStationCount = 100;
constexpr quint32 kMaxId = kIdBase + kMaxStation; // 0xC7; other IDs are reserved by the drive
constexpr quint8 kMaxParameterIndex = 219;        // parameters 0..219, int16
constexpr int kParameterCount = 220;
constexpr int kFrameLength = 8;          // DLC, always
constexpr quint8 kReservedByte = 0xFF;   // b7 ("reserved checksum, fill 0xFF")
constexpr quint8 kWriteParameter = 0x01; // b2 of a 0x15 write; other values are reserved
constexpr quint8 kHeartbeatIdle = 0x88;  // heartbeat state byte when idle
constexpr int kBitrate = 1000000;        // fixed by the drive

constexpr std::chrono::milliseconds kKeepAlivePeriod{100}; // host -> drive 0x08
constexpr std::chrono::milliseconds kHeartbeatPeriod{30};  // drive -> host 0x10
constexpr std::chrono::milliseconds kWatchdog{2000};       // drive stops without keep-alive
constexpr std::chrono::milliseconds kAlarmRepeat{2000};    // 0x05 repeated while alarmed

// Drive parameters named by the seed.
constexpr quint8 kParamControlMode = 4; // 8 = internal run control (needed for CAN control)
constexpr quint8 kParamCommMode = 74;   // 1 = CAN communication mode
constexpr quint8 kParamStation = 75;    // station number

// ---- Commands (b1) -----------------------------------------------------------------------
enum class Command : quint8 {
    Alarm = 0x05,            // drive -> host: b2 = code low, b3 = code high
    KeepAlive = 0x08,        // host -> drive, every 100 ms once a heartbeat was seen
    Heartbeat = 0x10,        // drive -> host every 30 ms: b2 = state, b3..b6 = position
    Read = 0x12,             // both: b2 = ReadType; the reply has the same layout, value filled
    Write = 0x15,            // host -> drive: b2 = 0x01, b3 = index, b5..b6 = int16 value
    RunSpeed = 0x20,         // host -> drive: speed mode at int32 speed (enables)
    MoveRelative = 0x21,     // host -> drive: relative int32 at the 0x23 speed (enables)
    MoveAbsolute = 0x22,     // host -> drive: absolute int32 target at the 0x23 speed (enables)
    PositioningSpeed = 0x23, // host -> drive: int32 positioning speed
    Enable = 0x25,           // host -> drive: b2 = 0 off, non-zero on
    Stop = 0x26,             // host -> drive: stop, stay enabled
    StopAndDisable = 0x28,   // host -> drive: stop and disable
    SetPosition = 0x50,      // host -> drive: current absolute position := int32
    ClearAlarm = 0x81        // host -> drive
};

enum class Direction { HostToDrive, DriveToHost, Both };

const std::array<Command, 14> &allCommands();
std::optional<Command> commandFromByte(quint8 b);
Direction commandDirection(Command c);
QString commandName(Command c); // technical English, e.g. "keep-alive" (for traces)

// ---- Read types (b2 of 0x12) -------------------------------------------------------------
enum class ReadType : quint8 {
    Parameter = 0xFA, // b3 = index, b4 = 0, b5..b6 = int16 value
    Speed = 0xFC,     // all others: int32 in b3..b6
    Position = 0xFD,
    Temperature = 0xA0,
    PositionCommand = 0xA1,
    PositionError = 0xA2,
    Torque = 0xA3,
    OutputCurrent = 0xA4, // two decimals: value / 100
    SpeedCommand = 0xA5,
    TorqueCommand = 0xA6,
    RotorPosition = 0xA7,
    InputIo = 0xA8,
    OutputIo = 0xA9,
    AlarmCode = 0xAA,
    BusVoltage = 0xAB
};

// How to present a read type. `name` and `unit` are English source strings registered with
// QT_TRANSLATE_NOOP in the context "dd::servocan": show them with
// QCoreApplication::translate("dd::servocan", info.name). Only the current scale and the
// speed unit come from the seed; the other units are this drive class's usual ones (hints).
struct ReadTypeInfo
{
    ReadType type;
    const char *key;  // stable identifier, e.g. "output-current" (CLI, files)
    const char *name; // e.g. "Output current"
    const char *unit; // e.g. "A"; empty when dimensionless
    double scale;     // engineering value = raw * scale
    int decimals;     // decimals to show
    bool bitField;    // IO states: show as hex / bits, not as a number
};

const std::array<ReadType, 15> &allReadTypes();
std::optional<ReadType> readTypeFromByte(quint8 b);
ReadTypeInfo readTypeInfo(ReadType t);
double scaledValue(ReadType t, qint32 raw); // raw * readTypeInfo(t).scale

// ---- Small helpers -----------------------------------------------------------------------
constexpr bool isValidStation(int station)
{
    return station >= 0 && station <= kMaxStation;
}
constexpr bool isValidParameterIndex(int index)
{
    return index >= 0 && index <= kMaxParameterIndex;
}
constexpr quint32 frameId(quint8 station)
{
    return kIdBase + station;
}
constexpr bool isHeartbeatIdle(quint8 state)
{
    return state == kHeartbeatIdle;
}

// ---- Encoders ----------------------------------------------------------------------------
// Every encoder returns ID 0x64 + station, standard format, 8 data bytes, b7 = 0xFF.
// Preconditions (asserted in debug builds, checked by the caller before sending):
// station 0..99, parameter index 0..219.

// Generic frame: [station][command][b2][value as int32 LE in b3..b6][0xFF].
CanFrameData frame(quint8 station, Command command, quint8 b2 = 0, qint32 value = 0);

// host -> drive
CanFrameData keepAlive(quint8 station);
CanFrameData readParameter(quint8 station, quint8 index);
CanFrameData read(quint8 station, ReadType type); // Parameter gives index 0; prefer readParameter
CanFrameData writeParameter(quint8 station, quint8 index, qint16 value);
CanFrameData runSpeed(quint8 station, qint32 speed);
CanFrameData moveRelative(quint8 station, qint32 distance);
CanFrameData moveAbsolute(quint8 station, qint32 target);
CanFrameData positioningSpeed(quint8 station, qint32 speed);
CanFrameData enable(quint8 station, bool on);
CanFrameData stop(quint8 station);
CanFrameData stopAndDisable(quint8 station);
CanFrameData setPosition(quint8 station, qint32 position);
CanFrameData clearAlarm(quint8 station);

// drive -> host
CanFrameData heartbeat(quint8 station, quint8 state, qint32 position);
CanFrameData alarm(quint8 station, quint16 code);
CanFrameData readReplyParameter(quint8 station, quint8 index, qint16 value);
CanFrameData readReply(quint8 station, ReadType type, qint32 value); // type != Parameter

// ---- Decoder -----------------------------------------------------------------------------
struct Message
{
    quint8 station = 0;
    Command command = Command::KeepAlive;
    quint8 b2 = 0;         // Read: type; Write: sub-code; Heartbeat: state; Enable: on/off;
                           // Alarm: code low byte
    quint8 paramIndex = 0; // b3 of a parameter frame (Read 0xFA, Write 0x01); else 0
    qint16 paramValue = 0; // b5..b6 of a parameter frame; else 0
    qint32 value = 0;      // b3..b6 as int32 LE (every frame)
    std::array<quint8, kFrameLength> raw{};
    // b7 is a "reserved checksum" the drive documents as always 0xFF and does not define
    // further. Decision: a frame with another b7 is accepted (a firmware that starts using
    // it must not make the drive disappear); this flag records the deviation for traces.
    bool reservedByteOk = true;

    bool isParameterFrame() const;            // Read with type 0xFA, or Write (sub 0x01)
    std::optional<ReadType> readType() const; // for Read frames
    quint16 alarmCode() const { return static_cast<quint16>(raw[2] | (raw[3] << 8)); }
    bool enableOn() const { return b2 != 0; }
    bool heartbeatIdle() const { return isHeartbeatIdle(b2); }
};

// Accepts frames of either direction (an echo of a host command decodes too). Rejects, with
// a specific English reason: extended ID, ID outside 0x64..0xC7, DLC != 8, b0 != ID - 0x64,
// unknown command, unknown read type (0x12), reserved write sub-code (0x15 b2 != 0x01),
// parameter index > 219 (0x12/0xFA and 0x15 frames).
// Lenient on purpose: b7 (see Message::reservedByteOk) and b4 of a parameter frame
// (documented as 0; the index is b3 alone) are not checked.
Decoded<Message> decode(const CanFrameData &frame);

// Pipelined reads: is `received` the reply to the read request (station, type, index)?
// Matches command 0x12, station and type, and the parameter index for type 0xFA.
bool isReplyTo(const Message &received, quint8 station, ReadType type, quint8 paramIndex = 0);
bool isReplyTo(const Message &received, const Message &request); // request: a decoded 0x12

} // namespace dd::servocan
