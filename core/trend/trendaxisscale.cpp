#include "core/trend/trendaxisscale.h"

#include <algorithm>
#include <cmath>

namespace dd {

double TrendAxisScale::niceStep(double rough)
{
    if (!(rough > 0.0) || !std::isfinite(rough))
        return 1.0;
    const double p = std::pow(10.0, std::floor(std::log10(rough)));
    const double m = rough / p;
    return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * p;
}

std::pair<double, double> TrendAxisScale::fitValueRange(double lo, double hi, double currentLo, double currentHi)
{
    if (hi - lo <= 1e-12 * std::max(1.0, std::fabs(hi))) {
        const double pad = std::max(1.0, std::fabs(hi) * 0.1);
        lo -= pad;
        hi += pad;
    } else {
        const double margin = (hi - lo) * 0.05;
        lo -= margin;
        hi += margin;
    }
    const bool fits = lo >= currentLo && hi <= currentHi;
    const bool loose = (hi - lo) < 0.5 * (currentHi - currentLo);
    if (fits && !loose)
        return {currentLo, currentHi};
    return {lo, hi};
}

} // namespace dd
