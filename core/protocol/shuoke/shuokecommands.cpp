#include "core/protocol/shuoke/shuokecommands.h"

#include <QCoreApplication>

#include <algorithm>

namespace dd::shuoke {

namespace {

constexpr quint16 L(int n)
{
    return static_cast<quint16>(1u << n);
}
constexpr quint16 L(int a, int b)
{
    return static_cast<quint16>(L(a) | L(b));
}
constexpr quint16 LRange(int from, int to)
{
    quint16 m = 0;
    for (int n = from; n <= to; ++n)
        m = static_cast<quint16>(m | L(n));
    return m;
}

CommandInfo entry(quint8 code, const char *name, quint16 request, quint16 reply, CommandFlags flags = NoFlags,
                  quint8 readCommand = 0, PlcAccess plc = PlcAccess::None, quint8 registers = 0, quint8 altReply = 0)
{
    CommandInfo c;
    c.code = code;
    c.name = name;
    c.requestLengths = request;
    c.replyLengths = reply;
    c.replyCommands[0] = code;
    c.replyCommands[1] = altReply;
    c.flags = flags;
    c.readCommand = readCommand;
    c.plcAccess = plc;
    c.plcRegisters = registers;
    return c;
}

constexpr PlcAccess R = PlcAccess::Read;
constexpr PlcAccess W = PlcAccess::Write;
constexpr PlcAccess None = PlcAccess::None;
const CommandFlags CL = CommandFlags(M6505Only) | ClosedLoop;

QList<CommandInfo> buildTable()
{
    // R/A lengths, flags, PLC access: docs/protocols/shuoke.md and the seed's RTU, CAN and
    // PLC chapters. PLC access is given only for the commands the seed's PLC chapter lists.
    return {
        entry(0x20, QT_TRANSLATE_NOOP("dd::shuoke", "Handshake"), L(0), L(0), NoCrcCheck, 0, R, 0),
        entry(0x21, QT_TRANSLATE_NOOP("dd::shuoke", "Query address"), L(0), L(0), BroadcastAllowed, 0, R, 0),
        entry(0x22, QT_TRANSLATE_NOOP("dd::shuoke", "Change address"), L(1), L(1), NoFlags, 0, W, 2),
        entry(0x23, QT_TRANSLATE_NOOP("dd::shuoke", "Get baud code"), L(0), L(1), NoFlags, 0, R, 2),
        entry(0x24, QT_TRANSLATE_NOOP("dd::shuoke", "Set baud code"), L(1), L(1), NoFlags, 0x23, W, 2),
        entry(0x25, QT_TRANSLATE_NOOP("dd::shuoke", "Set start speed"), L(4), L(0), NoFlags, 0x26, W, 2),
        entry(0x26, QT_TRANSLATE_NOOP("dd::shuoke", "Get start speed"), L(0), L(4), NoFlags, 0, R, 2),
        entry(0x27, QT_TRANSLATE_NOOP("dd::shuoke", "Set maximum speed"), L(4), L(0), NoFlags, 0x28, W, 2),
        entry(0x28, QT_TRANSLATE_NOOP("dd::shuoke", "Get maximum speed"), L(0), L(4), NoFlags, 0, R, 2),
        entry(0x29, QT_TRANSLATE_NOOP("dd::shuoke", "Set stop speed"), L(4), L(0), NoFlags, 0x2A, W, 2),
        entry(0x2A, QT_TRANSLATE_NOOP("dd::shuoke", "Get stop speed"), L(0), L(4), NoFlags, 0, R, 2),
        entry(0x2B, QT_TRANSLATE_NOOP("dd::shuoke", "Set acceleration"), L(4), L(0), NoFlags, 0x2C, W, 2),
        entry(0x2C, QT_TRANSLATE_NOOP("dd::shuoke", "Get acceleration"), L(0), L(4), NoFlags, 0, R, 2),
        entry(0x2D, QT_TRANSLATE_NOOP("dd::shuoke", "Set deceleration"), L(4), L(0), NoFlags, 0x2E, W, 2),
        entry(0x2E, QT_TRANSLATE_NOOP("dd::shuoke", "Get deceleration"), L(0), L(4), NoFlags, 0, R, 2),
        entry(0x2F, QT_TRANSLATE_NOOP("dd::shuoke", "Set homing speed"), L(4), L(0), NotM4505, 0x30, W, 2),
        entry(0x30, QT_TRANSLATE_NOOP("dd::shuoke", "Get homing speed"), L(0), L(4), NotM4505, 0, R, 2),
        entry(0x31, QT_TRANSLATE_NOOP("dd::shuoke", "Move relative (signed pulses)"), L(4), L(0), NoFlags, 0, W, 2),
        entry(0x32, QT_TRANSLATE_NOOP("dd::shuoke", "Move relative (direction + 24-bit pulses)"), L(4), L(0), NoFlags,
              0, W, 2),
        entry(0x33, QT_TRANSLATE_NOOP("dd::shuoke", "Run at constant speed (signed)"), L(4), L(0), NoFlags, 0, W, 2),
        entry(0x34, QT_TRANSLATE_NOOP("dd::shuoke", "Run at constant speed (direction + 24-bit)"), L(4), L(0), NoFlags,
              0, W, 2),
        entry(0x35, QT_TRANSLATE_NOOP("dd::shuoke", "Change speed while running"), L(4), L(0), NotM4505, 0, W, 2),
        entry(0x36, QT_TRANSLATE_NOOP("dd::shuoke", "Query speed"), L(0), L(4), NoFlags, 0, R, 2),
        entry(0x37, QT_TRANSLATE_NOOP("dd::shuoke", "Query absolute position"), L(0), L(4), NoFlags, 0, R, 2),
        entry(0x38, QT_TRANSLATE_NOOP("dd::shuoke", "Clear absolute position"), L(0), L(0), NoFlags, 0x37, W, 2),
        entry(0x39, QT_TRANSLATE_NOOP("dd::shuoke", "Query relative position"), L(0), L(4), NoFlags, 0, R, 2),
        entry(0x3A, QT_TRANSLATE_NOOP("dd::shuoke", "Clear relative position"), L(0), L(0), NoFlags, 0x39, W, 2),
        entry(0x3B, QT_TRANSLATE_NOOP("dd::shuoke", "Query status"), L(0), L(5), NoFlags, 0, R, 4),
        entry(0x3C, QT_TRANSLATE_NOOP("dd::shuoke", "Emergency stop"), L(0), L(0), BroadcastAllowed, 0, W, 2),
        entry(0x3D, QT_TRANSLATE_NOOP("dd::shuoke", "Decelerate to stop"), L(0), L(0), BroadcastAllowed, 0, W, 2),
        entry(0x3E, QT_TRANSLATE_NOOP("dd::shuoke", "Home"), L(1), L(0), NotM4505, 0, W, 2),
        entry(0x3F, QT_TRANSLATE_NOOP("dd::shuoke", "Set PLC mapping base"), L(2), L(0), WriteOnly),
        entry(0x40, QT_TRANSLATE_NOOP("dd::shuoke", "Set IO substitution entry"), LRange(1, 7), L(0),
              CommandFlags(NotM4505) | SerialOnly, 0x41),
        entry(0x41, QT_TRANSLATE_NOOP("dd::shuoke", "Read IO substitution entry"), L(1), LRange(0, 7),
              CommandFlags(NotM4505) | SerialOnly),
        entry(0x42, QT_TRANSLATE_NOOP("dd::shuoke", "Read inputs IO1..IO5"), L(0), L(5), NotM4505, 0, None, 0, 0x41),
        entry(0x43, QT_TRANSLATE_NOOP("dd::shuoke", "Read pulse, direction, enable, F1, F2 inputs"), L(0), L(5),
              NotM4505, 0, None, 0, 0x41),
        entry(0x44, QT_TRANSLATE_NOOP("dd::shuoke", "Set speed step F"), L(4), L(0), M4505SOnly, 0, None, 0, 0x41),
        entry(0x45, QT_TRANSLATE_NOOP("dd::shuoke", "Increase speed by F"), L(0), L(0), M4505SOnly, 0, None, 0, 0x41),
        entry(0x46, QT_TRANSLATE_NOOP("dd::shuoke", "Decrease speed by F"), L(0), L(0), M4505SOnly, 0, None, 0, 0x41),
        entry(0x47, QT_TRANSLATE_NOOP("dd::shuoke", "Factory reset"), L(0), L(0), M4505SOnly),
        entry(0x48, QT_TRANSLATE_NOOP("dd::shuoke", "Skip CRC check of received commands"), L(1), L(1),
              CommandFlags(M4505SOnly) | WriteOnly),
        entry(0x49, QT_TRANSLATE_NOOP("dd::shuoke", "Fixed-length replies"), L(1), L(1),
              CommandFlags(M4505SOnly) | WriteOnly),
        // The seed marks 0x4A..0x4D "M4505S only", but it also documents CAN for the
        // closed-loop M6505, which needs them: allowed for every model but the M4505.
        entry(0x4A, QT_TRANSLATE_NOOP("dd::shuoke", "CAN frame format"), L(1), L(1),
              CommandFlags(NotM4505) | WriteOnly),
        entry(0x4B, QT_TRANSLATE_NOOP("dd::shuoke", "CAN bitrate code"), L(1), L(1),
              CommandFlags(NotM4505) | WriteOnly),
        entry(0x4C, QT_TRANSLATE_NOOP("dd::shuoke", "Serial to CAN test echo"), L(5), L(5),
              CommandFlags(NotM4505) | SerialOnly),
        entry(0x4D, QT_TRANSLATE_NOOP("dd::shuoke", "CAN to serial test echo"), L(5), L(5),
              CommandFlags(NotM4505) | CanOnly),
        entry(0x4E, QT_TRANSLATE_NOOP("dd::shuoke", "Home (variant 2) / S-curve move (signed pulses)"), L(1, 4), L(0),
              NotM4505, 0, None, 0, 0x3E),
        entry(0x4F, QT_TRANSLATE_NOOP("dd::shuoke", "Home (variant 3) / S-curve move (direction + 24-bit)"), L(1, 4),
              L(0), NotM4505, 0, None, 0, 0x3E),
        entry(0x55, QT_TRANSLATE_NOOP("dd::shuoke", "Closed loop: move by feedback pulses"), L(4), L(0), CL, 0, W, 2),
        entry(0x56, QT_TRANSLATE_NOOP("dd::shuoke", "Closed loop: move by geared pulses"), L(4), L(0), CL, 0, W, 2),
        entry(0x57, QT_TRANSLATE_NOOP("dd::shuoke", "Closed loop: move to absolute position"), L(4), L(0), CL, 0, W, 2),
        entry(0x58, QT_TRANSLATE_NOOP("dd::shuoke", "Closed loop: read absolute position"), L(0), L(4), CL, 0, R, 2),
        entry(0x59, QT_TRANSLATE_NOOP("dd::shuoke", "Closed loop: set or clear absolute position"), L(0, 4), L(0), CL,
              0x58, W, 2),
        entry(0x5A, QT_TRANSLATE_NOOP("dd::shuoke", "Closed loop: read relative position"), L(0), L(4), CL, 0, R, 2),
        entry(0x5B, QT_TRANSLATE_NOOP("dd::shuoke", "Closed loop: set or clear relative position"), L(0, 4), L(0), CL,
              0x5A, W, 2),
        entry(0x5C, QT_TRANSLATE_NOOP("dd::shuoke", "Encoder direction"), L(1), L(0), CL | WriteOnly, 0, W, 1),
        entry(0x5D, QT_TRANSLATE_NOOP("dd::shuoke", "Motion direction"), L(1), L(0), CL | WriteOnly, 0, W, 1),
        entry(0x5E, QT_TRANSLATE_NOOP("dd::shuoke", "Accumulated-error correction"), L(1), L(0), CL | WriteOnly, 0, W,
              1),
        entry(0x5F, QT_TRANSLATE_NOOP("dd::shuoke", "Set gear numerator"), L(4), L(0), CL, 0x60, W, 2),
        entry(0x60, QT_TRANSLATE_NOOP("dd::shuoke", "Get gear numerator"), L(0), L(4), CL, 0, R, 2),
        entry(0x61, QT_TRANSLATE_NOOP("dd::shuoke", "Set gear denominator"), L(4), L(0), CL, 0x62, W, 2),
        entry(0x62, QT_TRANSLATE_NOOP("dd::shuoke", "Get gear denominator"), L(0), L(4), CL, 0, R, 2),
        entry(0x65, QT_TRANSLATE_NOOP("dd::shuoke", "Encoder A/B error tolerance"), L(4), L(0), CL | WriteOnly, 0, W,
              2),
        entry(0x66, QT_TRANSLATE_NOOP("dd::shuoke", "Maximum pulses without encoder signal"), L(4), L(0),
              CL | WriteOnly, 0, W, 2),
    };
}

int highestBit(quint16 mask)
{
    for (int n = 15; n >= 0; --n)
        if ((mask >> n) & 1u)
            return n;
    return -1;
}

} // namespace

int CommandInfo::maxRequestLength() const
{
    return highestBit(requestLengths);
}
int CommandInfo::maxReplyLength() const
{
    return highestBit(replyLengths);
}

QString modelName(Model model)
{
    switch (model) {
    case Model::M6505: return QStringLiteral("M6505");
    case Model::M4505: return QStringLiteral("M4505");
    case Model::M4505S: return QStringLiteral("M4505S");
    }
    return QString();
}

const QList<CommandInfo> &commandTable()
{
    static const QList<CommandInfo> table = buildTable();
    return table;
}

const CommandInfo *commandInfo(quint8 code)
{
    const QList<CommandInfo> &table = commandTable();
    const auto it = std::lower_bound(table.cbegin(), table.cend(), code,
                                     [](const CommandInfo &c, quint8 v) { return c.code < v; });
    return (it != table.cend() && it->code == code) ? &*it : nullptr;
}

QString commandName(quint8 code)
{
    if (const CommandInfo *c = commandInfo(code))
        return QString::fromLatin1(c->name);
    return QStringLiteral("command 0x%1").arg(code, 2, 16, QLatin1Char('0'));
}

bool isSupportedBy(quint8 code, Model model, int requestLength)
{
    const CommandInfo *c = commandInfo(code);
    if (!c)
        return false;
    if (code == CmdHomeOrSCurveInt32 || code == CmdHomeOrSCurveDirection24) {
        const bool homing = model != Model::M4505;  // 1 data byte
        const bool sCurve = model == Model::M4505S; // 4 data bytes
        if (requestLength == 1)
            return homing;
        if (requestLength == 4)
            return sCurve;
        return requestLength < 0 && (homing || sCurve);
    }
    if (requestLength >= 0 && !c->allowsRequestLength(requestLength))
        return false;
    if (c->flags.testFlag(M6505Only) && model != Model::M6505)
        return false;
    if (c->flags.testFlag(M4505SOnly) && model != Model::M4505S)
        return false;
    if (c->flags.testFlag(NotM4505) && model == Model::M4505)
        return false;
    return true;
}

QList<quint8> acceptedReplyCommands(const Frame &request)
{
    const CommandInfo *c = commandInfo(request.command);
    if (!c)
        return {request.command};
    if ((request.command == CmdHomeOrSCurveInt32 || request.command == CmdHomeOrSCurveDirection24)
        && request.data.size() == 4)
        return {request.command}; // S-curve move: answered with its own code
    QList<quint8> out{c->replyCommands[0]};
    if (c->replyCommands[1] != 0)
        out.append(c->replyCommands[1]);
    return out;
}

bool isKnownLayout(quint8 commandByte, int dataLength)
{
    if (commandByte & 0x80)
        return dataLength == 1; // a failure reply may name any command, even an unknown one
    for (const CommandInfo &c : commandTable()) {
        if (c.code == commandByte && (c.allowsRequestLength(dataLength) || c.allowsReplyLength(dataLength)))
            return true;
        if (c.replyCommands[1] == commandByte && c.allowsReplyLength(dataLength))
            return true;
    }
    return false;
}

bool isReplyAddress(quint8 replyAddress, const Frame &request)
{
    return isBroadcastAddress(request.address) || replyAddress == request.address
        || (request.command == CmdChangeAddress && request.data.size() == 1
            && replyAddress == static_cast<quint8>(request.data.at(0)));
}

bool isReplyTo(const Frame &reply, const Frame &request)
{
    if (!isReplyAddress(reply.address, request))
        return false;
    if (!acceptedReplyCommands(request).contains(reply.command))
        return false;
    if (reply.failure)
        return true;
    const CommandInfo *c = commandInfo(request.command);
    return !c || c->allowsReplyLength(static_cast<int>(reply.data.size()));
}

const char *failureCodeText(quint8 code)
{
    switch (code) {
    case FailureTimeoutOrLength: return QT_TRANSLATE_NOOP("dd::shuoke", "Receive timeout or wrong data length");
    case FailureChecksum: return QT_TRANSLATE_NOOP("dd::shuoke", "Checksum error");
    case FailureUnknownCommand: return QT_TRANSLATE_NOOP("dd::shuoke", "Unknown command");
    case FailureOutOfRange: return QT_TRANSLATE_NOOP("dd::shuoke", "Value out of range");
    case FailureNoBroadcast: return QT_TRANSLATE_NOOP("dd::shuoke", "Command does not support broadcast");
    default: return nullptr;
    }
}

QString failureDescription(quint8 code)
{
    if (const char *text = failureCodeText(code))
        return QString::fromLatin1(text);
    return QStringLiteral("unknown failure code 0x%1").arg(code, 2, 16, QLatin1Char('0'));
}

namespace {
constexpr int kBaudRates[] = {300, 600, 1200, 2400, 4800, 9600, 19200, 38400, 57600};
constexpr int kCanBitrates[] = {1000000, 900000, 800000, 750000, 600000, 500000, 400000, 250000, 200000,
                                150000,  125000, 100000, 80000,  50000,  25000,  20000,  10000,  5000};
} // namespace

int baudRateForCode(int code)
{
    return (code >= 1 && code <= kReservedBaudCode) ? kBaudRates[code - 1] : 0;
}

int baudCodeForRate(int baud)
{
    for (int i = 0; i < kReservedBaudCode; ++i)
        if (kBaudRates[i] == baud)
            return i + 1;
    return 0;
}

bool isUsableBaudCode(int code)
{
    return code >= kMinBaudCode && code <= kMaxBaudCode;
}

int canBitrateForCode(int code)
{
    return (code >= kMinCanBitrateCode && code <= kMaxCanBitrateCode) ? kCanBitrates[code - 1] : 0;
}

int canBitrateCodeFor(int bitrate)
{
    for (int i = 0; i < kMaxCanBitrateCode; ++i)
        if (kCanBitrates[i] == bitrate)
            return i + 1;
    return 0;
}

} // namespace dd::shuoke
