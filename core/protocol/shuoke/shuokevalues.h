#pragma once

#include <QByteArray>
#include <QString>
#include <QtGlobal>

#include <optional>

// Values carried in the data bytes of Shuoke commands.
//
// The seed never states the byte order of 32-bit data; its PLC examples put the low byte
// first. Decision (docs/protocols/shuoke.md): little-endian, with a per-link setting to flip it.
//
// "Direction + 24-bit" (0x32, 0x34, 0x4F as a move): the seed says the first byte is the
// direction (1 positive, 0 negative) and the pulse count is the "last 3 bytes", without
// their order. Decision: the direction byte comes first on the wire in both byte orders;
// the 24-bit magnitude follows low byte first (little-endian) or high byte first
// (big-endian) -- i.e. with the flip setting the 4 bytes read as one big-endian word
// (direction << 24 | magnitude).
namespace dd::shuoke {

enum class ByteOrder : quint8 { LittleEndian, BigEndian };

QByteArray encodeUInt32(quint32 value, ByteOrder order = ByteOrder::LittleEndian);
QByteArray encodeInt32(qint32 value, ByteOrder order = ByteOrder::LittleEndian);
QByteArray encodeUInt16(quint16 value, ByteOrder order = ByteOrder::LittleEndian); // 0x3F base
// nullopt unless `data` is exactly 4 (resp. 2) bytes.
std::optional<quint32> decodeUInt32(const QByteArray &data, ByteOrder order = ByteOrder::LittleEndian);
std::optional<qint32> decodeInt32(const QByteArray &data, ByteOrder order = ByteOrder::LittleEndian);
std::optional<quint16> decodeUInt16(const QByteArray &data, ByteOrder order = ByteOrder::LittleEndian);

constexpr qint32 kMaxMagnitude24 = 0xFFFFFF;
// Signed value as direction + 24-bit magnitude; 0 is sent as "positive". nullopt when
// |value| > 0xFFFFFF.
std::optional<QByteArray> encodeDirection24(qint32 value, ByteOrder order = ByteOrder::LittleEndian);
// nullopt unless 4 bytes with a direction byte of 0 or 1.
std::optional<qint32> decodeDirection24(const QByteArray &data, ByteOrder order = ByteOrder::LittleEndian);

// Speeds, start/stop speeds, accelerations, decelerations, speed step F: 0..100000
// pulses/s; the drive answers 0x04 beyond that, so the tool validates before sending.
constexpr qint64 kMaxSpeed = 100000;
constexpr bool isSpeedInRange(qint64 v)
{
    return v >= 0 && v <= kMaxSpeed;
}
constexpr bool isSignedSpeedInRange(qint64 v)
{
    return v >= -kMaxSpeed && v <= kMaxSpeed;
}
// Gear numerator / denominator: the drive uses 16 bits; the denominator must not be 0.
constexpr bool isGearNumeratorInRange(qint64 v)
{
    return v >= 0 && v <= 0xFFFF;
}
constexpr bool isGearDenominatorInRange(qint64 v)
{
    return v >= 1 && v <= 0xFFFF;
}
// Signed pulse counts of 0x31, 0x4E, 0x55, 0x56 ("31-bit" magnitude: INT32_MIN excluded).
constexpr bool isPulseCountInRange(qint64 v)
{
    return v >= -0x7FFFFFFFLL && v <= 0x7FFFFFFFLL;
}

// Checks a request's data against the command table (length) and the value ranges
// above (0x22 address 1..247, 0x24 baud code 1..8, 0x4B bitrate code 1..18, on/off
// bytes 0/1, IO substitution index 1..15, speeds, gears, pulse counts). Returns an empty
// string when the request may be sent, else an English reason.
QString validateRequestData(quint8 command, const QByteArray &data, ByteOrder order = ByteOrder::LittleEndian);

// Reply data of 0x3B (query status); nullopt unless at least 5 bytes.
struct MotionStatus
{
    bool running = false;
    bool leftLimit = false;
    bool origin = false;
    bool rightLimit = false;
    bool enableInput = false;

    bool operator==(const MotionStatus &o) const
    {
        return running == o.running && leftLimit == o.leftLimit && origin == o.origin && rightLimit == o.rightLimit
            && enableInput == o.enableInput;
    }
};
std::optional<MotionStatus> decodeMotionStatus(const QByteArray &data);
QByteArray encodeMotionStatus(const MotionStatus &status);

// Five 0/1 bytes of 0x42 (IO1..IO5) and 0x43 (pulse, direction, enable, F1, F2) as bits
// 0..4 (any non-zero byte counts as 1); nullopt unless exactly 5 bytes.
std::optional<quint8> decodeInputBits(const QByteArray &data);

} // namespace dd::shuoke
