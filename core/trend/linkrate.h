#pragma once

namespace dd {

// The default sample rate of a live monitor (the GUI trend, the CLI's `monitor`): as many
// readings a second as the link carries — 1e6 / Drive::channelReadUs() — rounded down to two
// significant digits, at most MaxHz, at least 0.1 Hz; `fallbackHz` when the read time is
// unknown (0).
struct LinkRate
{
    static constexpr double MaxHz = 1000.0;
    static double forReadUs(double readUs, double fallbackHz = 10.0);
};

} // namespace dd
