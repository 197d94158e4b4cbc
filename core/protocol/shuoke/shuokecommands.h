#pragma once

#include "core/protocol/shuoke/shuokeframe.h"

#include <QFlags>
#include <QList>
#include <QString>
#include <QtGlobal>

// The Shuoke command set as data (docs/protocols/shuoke.md, the seed). Names and failure
// texts are English source strings marked for translation in context "dd::shuoke":
// show them with QCoreApplication::translate("dd::shuoke", text).
namespace dd::shuoke {

enum class Model { M6505, M4505, M4505S };
QString modelName(Model model); // "M6505", "M4505", "M4505S"

enum CommandFlag : quint16 {
    NoFlags = 0,
    BroadcastAllowed = 0x0001, // the drive acts on it at the broadcast address
    NotM4505 = 0x0002,         // M6505 and M4505S only
    M6505Only = 0x0004,
    M4505SOnly = 0x0008,
    WriteOnly = 0x0010,  // a setting no command reads back
    SerialOnly = 0x0020, // the request is only accepted over RS232/RS485
    CanOnly = 0x0040,    // the request is only accepted over CAN (0x4D)
    ClosedLoop = 0x0080, // closed-loop (encoder) command of the M6505
    NoCrcCheck = 0x0100, // the drive does not check this request's CRC (0x20)
};
Q_DECLARE_FLAGS(CommandFlags, CommandFlag)

// How a command maps onto Modbus registers in PLC mode (seed: PLC section).
enum class PlcAccess : quint8 { None, Read, Write };

struct CommandInfo
{
    quint8 code = 0;
    const char *name = nullptr;       // English, marked QT_TRANSLATE_NOOP("dd::shuoke", ...)
    quint16 requestLengths = 0;       // bit n set: a request with n data bytes is valid
    quint16 replyLengths = 0;         // bit n set: a success reply with n data bytes is valid
    quint8 replyCommands[2] = {0, 0}; // accepted reply command codes (0 = unused slot)
    CommandFlags flags;
    quint8 readCommand = 0; // the command that reads back what this one sets; 0 none
    PlcAccess plcAccess = PlcAccess::None;
    quint8 plcRegisters = 0; // register count of the PLC read / write

    bool allowsRequestLength(int n) const { return n >= 0 && n < 16 && (requestLengths >> n) & 1u; }
    bool allowsReplyLength(int n) const { return n >= 0 && n < 16 && (replyLengths >> n) & 1u; }
    int maxRequestLength() const;
    int maxReplyLength() const;
};

// Every command code by name.
enum Command : quint8 {
    CmdHandshake = 0x20,
    CmdQueryAddress = 0x21,
    CmdChangeAddress = 0x22,
    CmdGetBaudCode = 0x23,
    CmdSetBaudCode = 0x24,
    CmdSetStartSpeed = 0x25,
    CmdGetStartSpeed = 0x26,
    CmdSetMaxSpeed = 0x27,
    CmdGetMaxSpeed = 0x28,
    CmdSetStopSpeed = 0x29,
    CmdGetStopSpeed = 0x2A,
    CmdSetAcceleration = 0x2B,
    CmdGetAcceleration = 0x2C,
    CmdSetDeceleration = 0x2D,
    CmdGetDeceleration = 0x2E,
    CmdSetHomingSpeed = 0x2F,
    CmdGetHomingSpeed = 0x30,
    CmdMoveRelative = 0x31,
    CmdMoveRelativeDirection24 = 0x32,
    CmdRunSpeed = 0x33,
    CmdRunSpeedDirection24 = 0x34,
    CmdChangeSpeed = 0x35,
    CmdQuerySpeed = 0x36,
    CmdQueryAbsolutePosition = 0x37,
    CmdClearAbsolutePosition = 0x38,
    CmdQueryRelativePosition = 0x39,
    CmdClearRelativePosition = 0x3A,
    CmdQueryStatus = 0x3B,
    CmdEmergencyStop = 0x3C,
    CmdDecelerateStop = 0x3D,
    CmdHome = 0x3E,
    CmdSetPlcBase = 0x3F,
    CmdSetIoSubstitution = 0x40,
    CmdReadIoSubstitution = 0x41,
    CmdReadInputs = 0x42,
    CmdReadOtherInputs = 0x43,
    CmdSetSpeedStep = 0x44,
    CmdSpeedStepUp = 0x45,
    CmdSpeedStepDown = 0x46,
    CmdFactoryReset = 0x47,
    CmdSkipCrcCheck = 0x48,
    CmdFixedLengthReplies = 0x49,
    CmdCanFrameFormat = 0x4A,
    CmdCanBitrate = 0x4B,
    CmdSerialToCanEcho = 0x4C,
    CmdCanToSerialEcho = 0x4D,
    CmdHomeOrSCurveInt32 = 0x4E,       // 1 byte: homing variant 2; 4 bytes: S-curve move
    CmdHomeOrSCurveDirection24 = 0x4F, // 1 byte: homing variant 3; 4 bytes: S-curve move
    CmdClosedLoopMove = 0x55,
    CmdClosedLoopGearedMove = 0x56,
    CmdClosedLoopMoveAbsolute = 0x57,
    CmdClosedLoopGetAbsolute = 0x58,
    CmdClosedLoopSetAbsolute = 0x59,
    CmdClosedLoopGetRelative = 0x5A,
    CmdClosedLoopSetRelative = 0x5B,
    CmdEncoderDirection = 0x5C,
    CmdMotionDirection = 0x5D,
    CmdErrorCorrection = 0x5E,
    CmdSetGearNumerator = 0x5F,
    CmdGetGearNumerator = 0x60,
    CmdSetGearDenominator = 0x61,
    CmdGetGearDenominator = 0x62,
    CmdEncoderAbTolerance = 0x65,
    CmdNoEncoderMaxPulses = 0x66,
};

// The whole table, ordered by code.
const QList<CommandInfo> &commandTable();
// The entry of `code` (without the failure bit); nullptr when the code is not a command.
const CommandInfo *commandInfo(quint8 code);
// English name of a command; "command 0xNN" for an unknown code.
QString commandName(quint8 code);

// Whether `model` supports the request. 0x4E/0x4F mean homing (1 data byte, not M4505)
// or an S-curve move (4 data bytes, M4505S only); requestLength < 0 means "either".
bool isSupportedBy(quint8 code, Model model, int requestLength = -1);

// Reply command codes accepted for `request`: the request's own code and the one the
// seed shows (0x41 for 0x42..0x46; 0x3E for the 1-byte homing forms of 0x4E/0x4F).
QList<quint8> acceptedReplyCommands(const Frame &request);

// True when a frame with this command byte (0x80 bit = failure) and this many data bytes
// is a layout some command of the table uses, as request or as reply. Stream parsers use
// it to judge the less likely interpretations of a frame.
bool isKnownLayout(quint8 commandByte, int dataLength);

// Broadcast address (decision, docs/protocols/shuoke.md: 0 by default, 255 as a setting).
enum class BroadcastAddress : quint8 { Zero = 0, AllOnes = 255 };
constexpr quint8 kBroadcastZero = 0;
constexpr quint8 kBroadcastAllOnes = 255;
constexpr quint8 broadcastAddress(BroadcastAddress setting)
{
    return static_cast<quint8>(setting);
}
constexpr bool isBroadcastAddress(quint8 address)
{
    return address == kBroadcastZero || address == kBroadcastAllOnes;
}
constexpr bool isUnicastAddress(int address)
{
    return address >= 1 && address <= 247;
}

// Whether a reply from `replyAddress` may answer `request`: any address answers a
// broadcast (0 or 255), 0x22 may answer from the old or the new address.
bool isReplyAddress(quint8 replyAddress, const Frame &request);

// Whether `reply` answers `request`: the address matches (any address answers a
// broadcast; 0x22 may answer from the old or the new address), the command is one of
// acceptedReplyCommands (for a failure: either of them with the 0x80 bit) and a success
// reply carries a data length the table allows.
bool isReplyTo(const Frame &reply, const Frame &request);

// Failure codes 0x01..0x05 of a failure reply.
enum FailureCode : quint8 {
    FailureTimeoutOrLength = 0x01,
    FailureChecksum = 0x02,
    FailureUnknownCommand = 0x03,
    FailureOutOfRange = 0x04,
    FailureNoBroadcast = 0x05,
};
// English text (marked for translation); nullptr for a code outside 1..5.
const char *failureCodeText(quint8 code);
// English text, or "unknown failure code 0xNN".
QString failureDescription(quint8 code);

// Serial baud codes of 0x23/0x24: 1=300 .. 8=38400; 9=57600 is reserved by the seed.
constexpr int kMinBaudCode = 1;
constexpr int kMaxBaudCode = 8;
constexpr int kReservedBaudCode = 9;
int baudRateForCode(int code);   // 0 when the code is not 1..9
int baudCodeForRate(int baud);   // 0 when the rate has no code (57600 gives 9)
bool isUsableBaudCode(int code); // 1..8

// CAN bitrate codes of 0x4B: 1=1 Mbit/s .. 18=5 kbit/s; default 12 (100 kbit/s).
constexpr int kMinCanBitrateCode = 1;
constexpr int kMaxCanBitrateCode = 18;
constexpr int kDefaultCanBitrateCode = 12;
int canBitrateForCode(int code);    // bit/s, 0 when the code is not 1..18
int canBitrateCodeFor(int bitrate); // 0 when the bitrate has no code

} // namespace dd::shuoke

Q_DECLARE_OPERATORS_FOR_FLAGS(dd::shuoke::CommandFlags)
