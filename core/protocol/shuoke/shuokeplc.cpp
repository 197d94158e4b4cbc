#include "core/protocol/shuoke/shuokeplc.h"

#include "core/common/hextext.h"
#include "core/protocol/modbus/crc16.h"
#include "core/protocol/shuoke/shuokecommands.h"

namespace dd::shuoke {

namespace {

template <typename T>
Decoded<T> plcFailure(const QString &why)
{
    return Decoded<T>::failure(QStringLiteral("PLC: ") + why);
}

quint16 word(const QByteArray &b, qsizetype at)
{
    return static_cast<quint16>((static_cast<quint8>(b.at(at)) << 8) | static_cast<quint8>(b.at(at + 1)));
}

void appendWord(QByteArray &b, quint16 v)
{
    b.append(static_cast<char>(v >> 8));
    b.append(static_cast<char>(v & 0xFF));
}

} // namespace

Decoded<PlcRequestLayout> plcRequestLayout(const Frame &request, const PlcOptions &options)
{
    const CommandInfo *info = commandInfo(request.command);
    if (!info || info->plcAccess == PlcAccess::None)
        return plcFailure<PlcRequestLayout>(
            QStringLiteral("command %1 has no PLC mapping").arg(hexText(request.command, 2)));
    if (request.failure)
        return plcFailure<PlcRequestLayout>(QStringLiteral("a failure reply is not a request"));
    const int reg = options.base + request.command;
    if (reg > 0xFFFF)
        return plcFailure<PlcRequestLayout>(QStringLiteral("base 0x%1 + command %2 exceeds the register range")
                                                .arg(options.base, 4, 16, QLatin1Char('0'))
                                                .arg(hexText(request.command, 2)));
    if (!info->allowsRequestLength(static_cast<int>(request.data.size())))
        return plcFailure<PlcRequestLayout>(QStringLiteral("command %1 does not take %2 data bytes")
                                                .arg(hexText(request.command, 2))
                                                .arg(request.data.size()));
    PlcRequestLayout layout;
    layout.registerAddress = static_cast<quint16>(reg);
    layout.registerCount = info->plcRegisters;
    if (info->plcAccess == PlcAccess::Read) {
        layout.function = PlcReadRegisters;
    } else {
        layout.function = PlcWriteRegisters;
        const int bytes = 2 * info->plcRegisters;
        if (request.data.size() > bytes)
            return plcFailure<PlcRequestLayout>(QStringLiteral("%1 data bytes do not fit %2 registers")
                                                    .arg(request.data.size())
                                                    .arg(info->plcRegisters));
        layout.values = request.data + QByteArray(bytes - request.data.size(), '\0');
    }
    return Decoded<PlcRequestLayout>::success(layout);
}

Decoded<QByteArray> encodePlcRequest(const Frame &request, const PlcOptions &options)
{
    const Decoded<PlcRequestLayout> layout = plcRequestLayout(request, options);
    if (!layout.ok())
        return Decoded<QByteArray>::failure(layout.error);
    QByteArray adu;
    adu.append(static_cast<char>(request.address));
    adu.append(static_cast<char>(layout.value->function));
    appendWord(adu, layout.value->registerAddress);
    appendWord(adu, layout.value->registerCount);
    if (layout.value->function == PlcWriteRegisters) {
        adu.append(static_cast<char>(layout.value->values.size()));
        adu.append(layout.value->values);
    }
    return Decoded<QByteArray>::success(withCrc16(adu));
}

int plcReplySize(const Frame &request)
{
    const CommandInfo *info = commandInfo(request.command);
    if (!info)
        return -1;
    switch (info->plcAccess) {
    case PlcAccess::Read: return 5 + 2 * info->plcRegisters;
    case PlcAccess::Write: return 8;
    case PlcAccess::None: break;
    }
    return -1;
}

Decoded<QByteArray> plcReplyData(quint8 command, const QByteArray &registerBytes)
{
    const CommandInfo *info = commandInfo(command);
    if (!info || info->plcAccess != PlcAccess::Read)
        return plcFailure<QByteArray>(QStringLiteral("command %1 is not a PLC read").arg(hexText(command, 2)));
    const int n = info->maxReplyLength();
    if (registerBytes.size() < n)
        return plcFailure<QByteArray>(
            QStringLiteral("%1 register bytes hold no %2-byte reply").arg(registerBytes.size()).arg(n));
    return Decoded<QByteArray>::success(registerBytes.left(n));
}

Decoded<Frame> decodePlcReply(const QByteArray &adu, const Frame &request, const PlcOptions &options)
{
    const Decoded<PlcRequestLayout> layout = plcRequestLayout(request, options);
    if (!layout.ok())
        return Decoded<Frame>::failure(layout.error);
    if (adu.size() < 5)
        return plcFailure<Frame>(QStringLiteral("reply of %1 bytes is too short").arg(adu.size()));
    if (!hasValidCrc16(adu))
        return plcFailure<Frame>(QStringLiteral("CRC mismatch"));
    const quint8 address = static_cast<quint8>(adu.at(0));
    if (!isReplyAddress(address, request))
        return plcFailure<Frame>(
            QStringLiteral("reply from address %1 to a request for %2").arg(address).arg(request.address));
    const quint8 function = static_cast<quint8>(adu.at(1));
    const quint8 expected = layout.value->function;
    if (function == (expected | 0x80)) {
        if (adu.size() != 5)
            return plcFailure<Frame>(QStringLiteral("exception reply of %1 bytes (5 expected)").arg(adu.size()));
        return Decoded<Frame>::success(Frame::failureReply(address, request.command, static_cast<quint8>(adu.at(2))));
    }
    if (function != expected)
        return plcFailure<Frame>(
            QStringLiteral("function %1 in reply, %2 expected").arg(hexText(function, 2), hexText(expected, 2)));

    if (expected == PlcReadRegisters) {
        const int byteCount = static_cast<quint8>(adu.at(2));
        if (byteCount != 2 * layout.value->registerCount)
            return plcFailure<Frame>(
                QStringLiteral("byte count %1, %2 expected").arg(byteCount).arg(2 * layout.value->registerCount));
        if (adu.size() != 5 + byteCount)
            return plcFailure<Frame>(
                QStringLiteral("reply of %1 bytes for a byte count of %2").arg(adu.size()).arg(byteCount));
        const Decoded<QByteArray> data = plcReplyData(request.command, adu.mid(3, byteCount));
        if (!data.ok())
            return Decoded<Frame>::failure(data.error);
        return Decoded<Frame>::success(Frame::make(address, request.command, *data.value));
    }
    if (adu.size() != 8)
        return plcFailure<Frame>(QStringLiteral("write reply of %1 bytes (8 expected)").arg(adu.size()));
    if (word(adu, 2) != layout.value->registerAddress || word(adu, 4) != layout.value->registerCount)
        return plcFailure<Frame>(QStringLiteral("write reply echoes register 0x%1 count %2, sent 0x%3 count %4")
                                     .arg(word(adu, 2), 4, 16, QLatin1Char('0'))
                                     .arg(word(adu, 4))
                                     .arg(layout.value->registerAddress, 4, 16, QLatin1Char('0'))
                                     .arg(layout.value->registerCount));
    return Decoded<Frame>::success(Frame::make(address, request.command));
}

Decoded<Frame> decodePlcRequest(const QByteArray &adu, const PlcOptions &options)
{
    if (adu.size() < 8)
        return plcFailure<Frame>(QStringLiteral("request of %1 bytes is too short").arg(adu.size()));
    if (!hasValidCrc16(adu))
        return plcFailure<Frame>(QStringLiteral("CRC mismatch"));
    const quint8 address = static_cast<quint8>(adu.at(0));
    const quint8 function = static_cast<quint8>(adu.at(1));
    const quint16 reg = word(adu, 2);
    const quint16 count = word(adu, 4);
    const int command = reg - options.base;
    const CommandInfo *info = (command >= 0 && command <= 0xFF) ? commandInfo(static_cast<quint8>(command)) : nullptr;
    if (!info || info->plcAccess == PlcAccess::None)
        return plcFailure<Frame>(QStringLiteral("register 0x%1 maps to no command (base 0x%2)")
                                     .arg(reg, 4, 16, QLatin1Char('0'))
                                     .arg(options.base, 4, 16, QLatin1Char('0')));
    const bool read = info->plcAccess == PlcAccess::Read;
    if (function != (read ? PlcReadRegisters : PlcWriteRegisters))
        return plcFailure<Frame>(
            QStringLiteral("function %1 for command %2").arg(hexText(function, 2), hexText(info->code, 2)));
    if (count != info->plcRegisters)
        return plcFailure<Frame>(QStringLiteral("%1 registers for command %2 (%3 expected)")
                                     .arg(count)
                                     .arg(hexText(info->code, 2))
                                     .arg(info->plcRegisters));
    if (read) {
        if (adu.size() != 8)
            return plcFailure<Frame>(QStringLiteral("read request of %1 bytes (8 expected)").arg(adu.size()));
        return Decoded<Frame>::success(Frame::make(address, info->code));
    }
    const int byteCount = static_cast<quint8>(adu.at(6));
    if (byteCount != 2 * count || adu.size() != 9 + byteCount)
        return plcFailure<Frame>(
            QStringLiteral("write request with byte count %1 in %2 bytes").arg(byteCount).arg(adu.size()));
    return Decoded<Frame>::success(Frame::make(address, info->code, adu.mid(7, info->maxRequestLength())));
}

Decoded<QByteArray> encodePlcReply(const Frame &reply, const Frame &request, const PlcOptions &options)
{
    const Decoded<PlcRequestLayout> layout = plcRequestLayout(request, options);
    if (!layout.ok())
        return Decoded<QByteArray>::failure(layout.error);
    QByteArray adu;
    adu.append(static_cast<char>(reply.address));
    if (reply.failure) {
        adu.append(static_cast<char>(layout.value->function | 0x80));
        adu.append(static_cast<char>(reply.failureCode));
        return Decoded<QByteArray>::success(withCrc16(adu));
    }
    adu.append(static_cast<char>(layout.value->function));
    if (layout.value->function == PlcReadRegisters) {
        const int bytes = 2 * layout.value->registerCount;
        if (reply.data.size() > bytes)
            return plcFailure<QByteArray>(QStringLiteral("%1 reply bytes do not fit %2 registers")
                                              .arg(reply.data.size())
                                              .arg(layout.value->registerCount));
        adu.append(static_cast<char>(bytes));
        adu.append(reply.data);
        adu.append(QByteArray(bytes - reply.data.size(), '\0'));
    } else {
        appendWord(adu, layout.value->registerAddress);
        appendWord(adu, layout.value->registerCount);
    }
    return Decoded<QByteArray>::success(withCrc16(adu));
}

QList<quint16> plcBytesToRegisters(const QByteArray &bytes)
{
    QList<quint16> out;
    out.reserve(bytes.size() / 2);
    for (qsizetype i = 0; i + 1 < bytes.size(); i += 2)
        out.append(word(bytes, i));
    return out;
}

QByteArray plcRegistersToBytes(const QList<quint16> &registers)
{
    QByteArray out;
    out.reserve(2 * registers.size());
    for (const quint16 r : registers)
        appendWord(out, r);
    return out;
}

} // namespace dd::shuoke
