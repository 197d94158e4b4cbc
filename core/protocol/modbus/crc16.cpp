#include "core/protocol/modbus/crc16.h"

namespace dd {

quint16 crc16Modbus(const char *data, qsizetype size)
{
    quint16 crc = 0xFFFF;
    for (qsizetype i = 0; i < size; ++i) {
        crc ^= static_cast<quint8>(data[i]);
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc & 1u) ? static_cast<quint16>((crc >> 1) ^ 0xA001u) : static_cast<quint16>(crc >> 1);
    }
    return crc;
}

QByteArray withCrc16(const QByteArray &frame)
{
    const quint16 crc = crc16Modbus(frame);
    QByteArray out = frame;
    out.append(static_cast<char>(crc & 0xFF));
    out.append(static_cast<char>(crc >> 8));
    return out;
}

bool hasValidCrc16(const QByteArray &frameWithCrc)
{
    if (frameWithCrc.size() < 3)
        return false;
    const qsizetype n = frameWithCrc.size() - 2;
    const quint16 crc = crc16Modbus(frameWithCrc.constData(), n);
    return static_cast<quint8>(frameWithCrc[n]) == (crc & 0xFF)
        && static_cast<quint8>(frameWithCrc[n + 1]) == (crc >> 8);
}

} // namespace dd
