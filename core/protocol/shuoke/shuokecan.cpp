#include "core/protocol/shuoke/shuokecan.h"

namespace dd::shuoke {

namespace {
Decoded<Frame> canFailure(const QString &why)
{
    return Decoded<Frame>::failure(QStringLiteral("CAN: ") + why);
}
} // namespace

Decoded<CanFrameData> encodeCan(const Frame &frame, const CanOptions &options)
{
    const QByteArray payload = frame.payload();
    if (payload.size() > kCanMaxData)
        return Decoded<CanFrameData>::failure(
            QStringLiteral("CAN: command 0x%1 with %2 data bytes does not fit an 8-byte CAN frame")
                .arg(frame.command, 2, 16, QLatin1Char('0'))
                .arg(payload.size()));
    CanFrameData can;
    can.extended = options.extended;
    can.id = (options.extended && options.extendedId == CanExtendedId::Zero) ? 0u : frame.address;
    can.data.reserve(kCanFrameBytes);
    can.data.append(static_cast<char>(frame.address));
    can.data.append(static_cast<char>(frame.commandByte()));
    can.data.append(static_cast<char>(payload.size()));
    can.data.append(payload);
    can.data.append(QByteArray(kCanFrameBytes - can.data.size(), '\0'));
    return Decoded<CanFrameData>::success(can);
}

Decoded<Frame> decodeCan(const CanFrameData &can)
{
    const QByteArray &d = can.data;
    if (d.size() > kCanFrameBytes)
        return canFailure(QStringLiteral("%1 data bytes (at most 8)").arg(d.size()));
    if (d.size() < 3)
        return canFailure(QStringLiteral("%1 data bytes is too short").arg(d.size()));
    const quint8 address = static_cast<quint8>(d.at(0));
    const quint8 commandByte = static_cast<quint8>(d.at(1));
    const int len = static_cast<quint8>(d.at(2));
    if (can.extended) {
        if (can.id != address && can.id != 0)
            return canFailure(
                QStringLiteral("extended id 0x%1 is neither the address %2 nor 0").arg(can.id, 0, 16).arg(address));
    } else if (can.id != address) {
        return canFailure(QStringLiteral("id 0x%1 does not match the address byte %2").arg(can.id, 0, 16).arg(address));
    }
    if (len > kCanMaxData || 3 + len > d.size())
        return canFailure(QStringLiteral("length byte %1 does not fit %2 data bytes").arg(len).arg(d.size()));
    if (commandByte & 0x80) {
        if (len != 1)
            return canFailure(QStringLiteral("failure reply with length %1 (one code byte expected)").arg(len));
        return Decoded<Frame>::success(Frame::failureReply(address, commandByte, static_cast<quint8>(d.at(3))));
    }
    return Decoded<Frame>::success(Frame::make(address, commandByte, d.mid(3, len)));
}

} // namespace dd::shuoke
