#include "core/protocol/shuoke/shuokertu.h"

#include "core/protocol/modbus/crc16.h"
#include "core/protocol/shuoke/shuokecommands.h"

namespace dd::shuoke {

namespace detail {

QList<RtuCandidate> rtuCandidates(quint8 commandByte, quint8 len, const RtuOptions &options)
{
    const bool failure = (commandByte & 0x80) != 0;
    auto dataOk = [failure](int n) { return n >= 0 && (!failure || n == 1); };
    QList<RtuCandidate> out;
    if (dataOk(len))
        out.append({kRtuOverhead + len, len, RtuLayout::Standard});
    if (options.acceptLengthWithCrc && dataOk(len - 2))
        out.append({3 + len, len - 2, RtuLayout::LengthCountsCrc});
    if (options.acceptFixedLength && len < kFixedDataSize && dataOk(len))
        out.append({kFixedFrameSize, len, RtuLayout::FixedLength}); // len 5 is Standard already
    return out;
}

bool rtuCandidateMatches(const char *p, const RtuCandidate &c, const RtuOptions &options)
{
    const quint8 commandByte = static_cast<quint8>(p[1]);
    if (c.layout != RtuLayout::Standard && !isKnownLayout(commandByte, c.dataLength))
        return false;
    if (options.skipHandshakeCrc && commandByte == CmdHandshake && c.layout == RtuLayout::Standard)
        return true;
    const quint16 crc = crc16Modbus(p, c.size - 2);
    return static_cast<quint8>(p[c.size - 2]) == (crc & 0xFF) && static_cast<quint8>(p[c.size - 1]) == (crc >> 8);
}

Frame rtuFrameFrom(const char *p, const RtuCandidate &c)
{
    const quint8 address = static_cast<quint8>(p[0]);
    const quint8 commandByte = static_cast<quint8>(p[1]);
    if (commandByte & 0x80)
        return Frame::failureReply(address, commandByte, static_cast<quint8>(p[3]));
    return Frame::make(address, commandByte, QByteArray(p + 3, c.dataLength));
}

} // namespace detail

Decoded<QByteArray> encodeRtu(const Frame &frame, const RtuOptions &options)
{
    const QByteArray payload = frame.payload();
    if (payload.size() > 255)
        return Decoded<QByteArray>::failure(
            QStringLiteral("RTU: %1 data bytes do not fit the length byte").arg(payload.size()));
    QByteArray out;
    out.reserve(kFixedFrameSize + payload.size());
    out.append(static_cast<char>(frame.address));
    out.append(static_cast<char>(frame.commandByte()));
    out.append(static_cast<char>(payload.size()));
    out.append(payload);
    if (options.padToFixedLength && payload.size() < kFixedDataSize)
        out.append(QByteArray(kFixedDataSize - payload.size(), '\0'));
    return Decoded<QByteArray>::success(withCrc16(out));
}

Decoded<Frame> decodeRtu(const QByteArray &bytes, const RtuOptions &options, RtuLayout *layout)
{
    using detail::RtuCandidate;
    if (bytes.size() < kRtuMinFrameSize)
        return Decoded<Frame>::failure(QStringLiteral("RTU: frame of %1 bytes is too short").arg(bytes.size()));
    const quint8 commandByte = static_cast<quint8>(bytes.at(1));
    const quint8 len = static_cast<quint8>(bytes.at(2));
    const QList<RtuCandidate> candidates = detail::rtuCandidates(commandByte, len, options);
    bool standardSize = false;
    for (const RtuCandidate &c : candidates) {
        if (c.size != bytes.size())
            continue;
        standardSize = standardSize || c.layout == RtuLayout::Standard;
        if (detail::rtuCandidateMatches(bytes.constData(), c, options)) {
            if (layout)
                *layout = c.layout;
            return Decoded<Frame>::success(detail::rtuFrameFrom(bytes.constData(), c));
        }
    }
    if ((commandByte & 0x80) && candidates.isEmpty())
        return Decoded<Frame>::failure(
            QStringLiteral("RTU: failure reply with length %1 (one code byte expected)").arg(len));
    const quint16 expected = crc16Modbus(bytes.constData(), bytes.size() - 2);
    const quint16 got = static_cast<quint16>(static_cast<quint8>(bytes.at(bytes.size() - 2))
                                             | (static_cast<quint8>(bytes.at(bytes.size() - 1)) << 8));
    if (!standardSize || got == expected)
        return Decoded<Frame>::failure(
            QStringLiteral("RTU: length byte %1 does not fit a frame of %2 bytes").arg(len).arg(bytes.size()));
    return Decoded<Frame>::failure(QStringLiteral("RTU: CRC mismatch (frame has %1, computed %2)")
                                       .arg(got, 4, 16, QLatin1Char('0'))
                                       .arg(expected, 4, 16, QLatin1Char('0')));
}

} // namespace dd::shuoke
