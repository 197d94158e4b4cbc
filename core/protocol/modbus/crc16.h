#pragma once

#include <QByteArray>
#include <QtGlobal>

namespace dd {

// CRC-16/MODBUS (poly 0xA001 reflected, init 0xFFFF). On the wire: low byte first.
quint16 crc16Modbus(const char *data, qsizetype size);
inline quint16 crc16Modbus(const QByteArray &data)
{
    return crc16Modbus(data.constData(), data.size());
}

// Appends the CRC of `frame` to it, low byte first.
QByteArray withCrc16(const QByteArray &frame);
// True when the last two bytes are the CRC (low first) of the bytes before them.
bool hasValidCrc16(const QByteArray &frameWithCrc);

} // namespace dd
