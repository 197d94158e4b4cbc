#pragma once

#include <QByteArray>

namespace dd {

// What a UART set to one baud rate makes of bytes sent at another: the sent bytes are laid
// out as a bit waveform (idle high, start bit low, 8 data bits LSB first, stop bit(s) high,
// characters back to back), and a receiver at `receiverBaud` looks for each falling edge and
// samples the middle of its start, data and stop bits, exactly like a UART (without
// oversampling jitter). A character whose stop bit samples low is delivered as 0x00, as
// Linux does for a framing error in raw mode.
//
// Used by SimSerialBus so that a drive set to a different rate than the host receives the
// same kind of garbage a real one would: deterministic, usually a different number of bytes,
// practically never a frame with a valid checksum. With equal rates the bytes pass unchanged.
class UartResampler
{
public:
    UartResampler() = delete;

    static QByteArray resample(const QByteArray &bytes, int sentBaud, int receiverBaud, int bitsPerChar = 10);
};

} // namespace dd
