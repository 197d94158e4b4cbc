#include "core/link/wiretime.h"

#include <algorithm>

namespace dd {

namespace {
constexpr int ModbusFixedTimingAboveBaud = 19200;
constexpr double ModbusFixedSilenceUs = 1750.0;
constexpr double ModbusFixedInterCharUs = 750.0;
constexpr int CanStandardStuffedBits = 34; // SOF .. CRC without data, 11-bit ID
constexpr int CanExtendedStuffedBits = 54; // SOF .. CRC without data, 29-bit ID
constexpr int CanTrailerBits = 10;         // CRC delim, ACK slot, ACK delim, EOF (never stuffed)
} // namespace

double WireTime::serialCharUs(int baud, int bitsPerChar)
{
    if (baud <= 0 || bitsPerChar <= 0)
        return 0.0;
    return 1e6 * bitsPerChar / baud;
}

double WireTime::serialBytesUs(qsizetype bytes, int baud, int bitsPerChar)
{
    if (bytes <= 0)
        return 0.0;
    return static_cast<double>(bytes) * serialCharUs(baud, bitsPerChar);
}

double WireTime::modbusSilenceUs(int baud, int bitsPerChar)
{
    const double t = 3.5 * serialCharUs(baud, bitsPerChar);
    return baud > ModbusFixedTimingAboveBaud ? std::max(t, ModbusFixedSilenceUs) : t;
}

double WireTime::modbusSameDriveSilenceUs(int baud, int bitsPerChar)
{
    return 3.5 * serialCharUs(baud, bitsPerChar);
}

double WireTime::modbusInterCharUs(int baud, int bitsPerChar)
{
    const double t = 1.5 * serialCharUs(baud, bitsPerChar);
    return baud > ModbusFixedTimingAboveBaud ? std::max(t, ModbusFixedInterCharUs) : t;
}

int WireTime::canFrameBits(int dlc, bool extended, CanStuffing stuffing)
{
    const int n = std::clamp(dlc, 0, 8);
    const int stuffed = (extended ? CanExtendedStuffedBits : CanStandardStuffedBits) + 8 * n;
    const int stuffBits = stuffing == CanStuffing::WorstCase ? (stuffed - 1) / 4 : 0;
    return stuffed + stuffBits + CanTrailerBits + CanIntermissionBits;
}

double WireTime::canFrameUs(int dlc, bool extended, int bitrate, CanStuffing stuffing)
{
    if (bitrate <= 0)
        return 0.0;
    return 1e6 * canFrameBits(dlc, extended, stuffing) / bitrate;
}

} // namespace dd
