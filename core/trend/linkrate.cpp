#include "core/trend/linkrate.h"

#include <algorithm>
#include <cmath>

namespace dd {

double LinkRate::forReadUs(double readUs, double fallbackHz)
{
    if (!(readUs > 0.0))
        return fallbackHz;
    const double hz = std::min(MaxHz, 1e6 / readUs);
    const double unit = std::pow(10.0, std::floor(std::log10(hz)) - 1); // two digits
    return std::max(0.1, std::floor(hz / unit) * unit);
}

} // namespace dd
