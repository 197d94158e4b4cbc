#pragma once

#include <utility>

namespace dd {

// Axis arithmetic for trend plots (pure functions).
class TrendAxisScale
{
public:
    // A 1-2-5 × 10^k step near `rough` (1 for non-positive or non-finite input): tick
    // intervals that stay on round values while a time axis scrolls.
    static double niceStep(double rough);

    // The value-axis range for data spanning [lo, hi] when the axis shows
    // [currentLo, currentHi]: the data plus a 5 % margin each side (±max(1, 10 %) around a
    // flat line). With hysteresis: the current range is kept while the data fits in it
    // and fills at least half of it, so a noisy signal does not make the axis twitch.
    static std::pair<double, double> fitValueRange(double lo, double hi, double currentLo, double currentHi);
};

} // namespace dd
