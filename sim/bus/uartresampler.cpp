#include "sim/bus/uartresampler.h"

#include <algorithm>

namespace dd {

namespace {
// The sent waveform. Time is counted in integer ticks so that sample instants that fall
// exactly on a bit boundary (integer baud ratios) are decided the same way everywhere:
// one sent bit lasts `bitTicks`, one received bit `rxBitTicks`.
struct Waveform
{
    const QByteArray &bytes;
    int bitsPerChar;
    qint64 bitTicks;

    qint64 endTicks() const { return static_cast<qint64>(bytes.size()) * bitsPerChar * bitTicks; }

    // Line level at tick t: true = high (mark / idle).
    bool level(qint64 t) const
    {
        if (t < 0 || t >= endTicks())
            return true;
        const qint64 bit = t / bitTicks;
        const qint64 ch = bit / bitsPerChar;
        const int pos = static_cast<int>(bit % bitsPerChar);
        if (pos == 0)
            return false; // start bit
        if (pos <= 8)
            return (static_cast<quint8>(bytes[ch]) >> (pos - 1)) & 1u; // data, LSB first
        return true;                                                   // stop bit(s)
    }

    // First falling edge at or after tick `from` (edges sit on sent-bit boundaries), or -1.
    qint64 nextFallingEdge(qint64 from) const
    {
        qint64 boundary = std::max<qint64>(0, (from + bitTicks - 1) / bitTicks);
        const qint64 lastBoundary = endTicks() / bitTicks;
        for (; boundary < lastBoundary; ++boundary) {
            const qint64 t = boundary * bitTicks;
            if (!level(t) && level(t - 1))
                return t;
        }
        return -1;
    }
};
} // namespace

QByteArray UartResampler::resample(const QByteArray &bytes, int sentBaud, int receiverBaud, int bitsPerChar)
{
    if (bytes.isEmpty() || sentBaud <= 0 || receiverBaud <= 0 || sentBaud == receiverBaud)
        return bytes;
    bitsPerChar = std::max(bitsPerChar, 10);

    // 1 tick = 1 / (2 · sentBaud · receiverBaud) s: both bit times and the half receive bit
    // are whole numbers of ticks.
    const Waveform wave{bytes, bitsPerChar, 2 * static_cast<qint64>(receiverBaud)};
    const qint64 rxBit = 2 * static_cast<qint64>(sentBaud);
    const qint64 rxHalf = static_cast<qint64>(sentBaud);

    QByteArray out;
    qint64 searchFrom = 0;
    for (;;) {
        const qint64 edge = wave.nextFallingEdge(searchFrom);
        if (edge < 0)
            break;
        if (wave.level(edge + rxHalf)) {
            searchFrom = edge + rxHalf; // glitch, not a start bit
            continue;
        }
        quint8 value = 0;
        for (int b = 0; b < 8; ++b) {
            if (wave.level(edge + rxHalf + (b + 1) * rxBit))
                value |= static_cast<quint8>(1u << b);
        }
        const qint64 stopSample = edge + rxHalf + 9 * rxBit;
        const bool framingError = !wave.level(stopSample);
        out.append(static_cast<char>(framingError ? 0 : value));
        searchFrom = stopSample;
    }
    return out;
}

} // namespace dd
