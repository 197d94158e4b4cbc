#include "core/protocol/shuoke/shuokevalues.h"

#include "core/common/hextext.h"
#include "core/protocol/shuoke/shuokecommands.h"

namespace dd::shuoke {

namespace {

QByteArray encodeUnsigned(quint32 value, int bytes, ByteOrder order)
{
    QByteArray out(bytes, '\0');
    for (int i = 0; i < bytes; ++i) {
        const int index = order == ByteOrder::LittleEndian ? i : bytes - 1 - i;
        out[index] = static_cast<char>((value >> (8 * i)) & 0xFF);
    }
    return out;
}

quint32 decodeUnsigned(const char *p, int bytes, ByteOrder order)
{
    quint32 value = 0;
    for (int i = 0; i < bytes; ++i) {
        const int index = order == ByteOrder::LittleEndian ? i : bytes - 1 - i;
        value |= static_cast<quint32>(static_cast<quint8>(p[index])) << (8 * i);
    }
    return value;
}

QString checkFlag(const QByteArray &data, const char *what)
{
    const quint8 v = static_cast<quint8>(data.at(0));
    return v <= 1 ? QString() : QStringLiteral("%1 must be 0 or 1, got %2").arg(QLatin1String(what)).arg(v);
}

} // namespace

QByteArray encodeUInt32(quint32 value, ByteOrder order)
{
    return encodeUnsigned(value, 4, order);
}
QByteArray encodeInt32(qint32 value, ByteOrder order)
{
    return encodeUnsigned(static_cast<quint32>(value), 4, order);
}
QByteArray encodeUInt16(quint16 value, ByteOrder order)
{
    return encodeUnsigned(value, 2, order);
}

std::optional<quint32> decodeUInt32(const QByteArray &data, ByteOrder order)
{
    if (data.size() != 4)
        return std::nullopt;
    return decodeUnsigned(data.constData(), 4, order);
}

std::optional<qint32> decodeInt32(const QByteArray &data, ByteOrder order)
{
    if (data.size() != 4)
        return std::nullopt;
    return static_cast<qint32>(decodeUnsigned(data.constData(), 4, order));
}

std::optional<quint16> decodeUInt16(const QByteArray &data, ByteOrder order)
{
    if (data.size() != 2)
        return std::nullopt;
    return static_cast<quint16>(decodeUnsigned(data.constData(), 2, order));
}

std::optional<QByteArray> encodeDirection24(qint32 value, ByteOrder order)
{
    if (value > kMaxMagnitude24 || value < -kMaxMagnitude24)
        return std::nullopt;
    const quint32 magnitude = static_cast<quint32>(value < 0 ? -value : value);
    QByteArray out(1, value < 0 ? '\0' : '\1');
    out += encodeUnsigned(magnitude, 3, order);
    return out;
}

std::optional<qint32> decodeDirection24(const QByteArray &data, ByteOrder order)
{
    if (data.size() != 4)
        return std::nullopt;
    const quint8 direction = static_cast<quint8>(data.at(0));
    if (direction > 1)
        return std::nullopt;
    const qint32 magnitude = static_cast<qint32>(decodeUnsigned(data.constData() + 1, 3, order));
    return direction == 1 ? magnitude : -magnitude;
}

QString validateRequestData(quint8 command, const QByteArray &data, ByteOrder order)
{
    const CommandInfo *info = commandInfo(command);
    if (!info)
        return QStringLiteral("unknown command %1").arg(hexText(command, 2));
    const int n = static_cast<int>(data.size());
    if (!info->allowsRequestLength(n))
        return QStringLiteral("command %1 (%2) does not take %3 data bytes")
            .arg(hexText(command, 2), QLatin1String(info->name))
            .arg(n);
    if (n == 0)
        return QString();

    switch (command) {
    case 0x22: {
        const quint8 a = static_cast<quint8>(data.at(0));
        return isUnicastAddress(a) ? QString() : QStringLiteral("address must be 1..247, got %1").arg(a);
    }
    case 0x24: {
        const int code = static_cast<quint8>(data.at(0));
        if (code == kReservedBaudCode)
            return QStringLiteral("baud code 9 (57600) is reserved by the drive");
        return isUsableBaudCode(code) ? QString() : QStringLiteral("baud code must be 1..8, got %1").arg(code);
    }
    case 0x25:
    case 0x27:
    case 0x29:
    case 0x2B:
    case 0x2D:
    case 0x2F:
    case 0x35:
    case 0x44: {
        const quint32 v = *decodeUInt32(data, order);
        return isSpeedInRange(v) ? QString() : QStringLiteral("speed must be 0..100000, got %1").arg(v);
    }
    case 0x33: {
        const qint32 v = *decodeInt32(data, order);
        return isSignedSpeedInRange(v) ? QString() : QStringLiteral("speed must be -100000..100000, got %1").arg(v);
    }
    case 0x34: {
        const auto v = decodeDirection24(data, order);
        if (!v)
            return QStringLiteral("direction byte must be 0 or 1");
        return isSignedSpeedInRange(*v) ? QString() : QStringLiteral("speed must be 0..100000, got %1").arg(qAbs(*v));
    }
    case 0x32: return decodeDirection24(data, order) ? QString() : QStringLiteral("direction byte must be 0 or 1");
    case 0x31:
    case 0x55:
    case 0x56:
    case 0x57: {
        const qint32 v = *decodeInt32(data, order);
        return isPulseCountInRange(v) ? QString() : QStringLiteral("pulse count out of the 31-bit range");
    }
    case 0x4E:
    case 0x4F:
        if (n == 1)
            return checkFlag(data, "homing direction");
        if (command == 0x4E)
            return isPulseCountInRange(*decodeInt32(data, order))
                ? QString()
                : QStringLiteral("pulse count out of the 31-bit range");
        return decodeDirection24(data, order) ? QString() : QStringLiteral("direction byte must be 0 or 1");
    case 0x3E: return checkFlag(data, "homing direction");
    case 0x48:
    case 0x49:
    case 0x4A:
    case 0x5C:
    case 0x5D:
    case 0x5E: return checkFlag(data, "setting");
    case 0x4B: {
        const int code = static_cast<quint8>(data.at(0));
        return canBitrateForCode(code) ? QString() : QStringLiteral("CAN bitrate code must be 1..18, got %1").arg(code);
    }
    case 0x40:
    case 0x41: {
        const int index = static_cast<quint8>(data.at(0));
        return (index >= 1 && index <= 15) ? QString()
                                           : QStringLiteral("IO substitution index must be 1..15, got %1").arg(index);
    }
    case 0x5F: {
        const quint32 v = *decodeUInt32(data, order);
        return isGearNumeratorInRange(v) ? QString() : QStringLiteral("gear numerator must be 0..65535, got %1").arg(v);
    }
    case 0x61: {
        const quint32 v = *decodeUInt32(data, order);
        return isGearDenominatorInRange(v) ? QString()
                                           : QStringLiteral("gear denominator must be 1..65535, got %1").arg(v);
    }
    default: return QString();
    }
}

std::optional<MotionStatus> decodeMotionStatus(const QByteArray &data)
{
    if (data.size() < 5)
        return std::nullopt;
    MotionStatus s;
    s.running = data.at(0) != 0;
    s.leftLimit = data.at(1) != 0;
    s.origin = data.at(2) != 0;
    s.rightLimit = data.at(3) != 0;
    s.enableInput = data.at(4) != 0;
    return s;
}

QByteArray encodeMotionStatus(const MotionStatus &s)
{
    QByteArray out(5, '\0');
    out[0] = s.running ? 1 : 0;
    out[1] = s.leftLimit ? 1 : 0;
    out[2] = s.origin ? 1 : 0;
    out[3] = s.rightLimit ? 1 : 0;
    out[4] = s.enableInput ? 1 : 0;
    return out;
}

std::optional<quint8> decodeInputBits(const QByteArray &data)
{
    if (data.size() != 5)
        return std::nullopt;
    quint8 bits = 0;
    for (int i = 0; i < 5; ++i)
        if (data.at(i) != 0)
            bits = static_cast<quint8>(bits | (1u << i));
    return bits;
}

} // namespace dd::shuoke
