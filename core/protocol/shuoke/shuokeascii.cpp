#include "core/protocol/shuoke/shuokeascii.h"

namespace dd::shuoke {

namespace {

int hexValue(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    return -1;
}

Decoded<Frame> asciiFailure(const QString &why)
{
    return Decoded<Frame>::failure(QStringLiteral("ASCII: ") + why);
}

} // namespace

quint8 asciiCheckByte(const QByteArray &bytes, AsciiCheck check)
{
    quint8 sum = 0;
    for (const char c : bytes)
        sum = static_cast<quint8>(sum + static_cast<quint8>(c));
    return check == AsciiCheck::PlainSum ? sum : static_cast<quint8>(-sum);
}

Decoded<QByteArray> encodeAscii(const Frame &frame, const AsciiOptions &options)
{
    const QByteArray payload = frame.payload();
    if (payload.size() > 255)
        return Decoded<QByteArray>::failure(
            QStringLiteral("ASCII: %1 data bytes do not fit the length byte").arg(payload.size()));
    QByteArray bytes;
    bytes.append(static_cast<char>(frame.address));
    bytes.append(static_cast<char>(frame.commandByte()));
    bytes.append(static_cast<char>(payload.size()));
    bytes.append(payload);
    bytes.append(static_cast<char>(asciiCheckByte(bytes, options.check)));
    return Decoded<QByteArray>::success(kAsciiStart + bytes.toHex().toUpper() + "\r\n");
}

Decoded<Frame> decodeAscii(const QByteArray &line, const AsciiOptions &options)
{
    if (line.isEmpty() || line.at(0) != kAsciiStart)
        return asciiFailure(QStringLiteral("frame does not start with ':'"));
    if (!line.endsWith('\n'))
        return asciiFailure(QStringLiteral("frame does not end with CR LF"));
    qsizetype end = line.size() - 1;
    if (end > 1 && line.at(end - 1) == '\r')
        --end;
    const qsizetype digits = end - 1;
    if (digits % 2 != 0)
        return asciiFailure(QStringLiteral("odd number of hex digits (%1)").arg(digits));
    QByteArray bytes;
    bytes.reserve(digits / 2);
    for (qsizetype i = 1; i < end; i += 2) {
        const int hi = hexValue(line.at(i));
        const int lo = hexValue(line.at(i + 1));
        if (hi < 0 || lo < 0)
            return asciiFailure(QStringLiteral("non-hex character at position %1").arg(hi < 0 ? i : i + 1));
        bytes.append(static_cast<char>(hi * 16 + lo));
    }
    if (bytes.size() < 4)
        return asciiFailure(QStringLiteral("frame of %1 bytes is too short").arg(bytes.size()));

    const quint8 check = static_cast<quint8>(bytes.back());
    bytes.chop(1);
    const quint8 expected = asciiCheckByte(bytes, options.check);
    if (check != expected)
        return asciiFailure(QStringLiteral("check byte mismatch (frame has %1, computed %2)")
                                .arg(check, 2, 16, QLatin1Char('0'))
                                .arg(expected, 2, 16, QLatin1Char('0')));

    const quint8 address = static_cast<quint8>(bytes.at(0));
    const quint8 commandByte = static_cast<quint8>(bytes.at(1));
    const int len = static_cast<quint8>(bytes.at(2));
    const int dataCount = static_cast<int>(bytes.size()) - 3;
    if (len != dataCount && !(options.acceptLengthPlusOne && len == dataCount + 1))
        return asciiFailure(QStringLiteral("length byte %1 does not match %2 data bytes").arg(len).arg(dataCount));
    if (commandByte & 0x80) {
        if (dataCount != 1)
            return asciiFailure(
                QStringLiteral("failure reply with %1 data bytes (one code byte expected)").arg(dataCount));
        return Decoded<Frame>::success(Frame::failureReply(address, commandByte, static_cast<quint8>(bytes.at(3))));
    }
    return Decoded<Frame>::success(Frame::make(address, commandByte, bytes.mid(3)));
}

} // namespace dd::shuoke
