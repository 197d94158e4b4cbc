#include "core/trend/trendplotbuilder.h"

#include "core/trend/decimator.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dd {

TrendPlotBuilder::Result TrendPlotBuilder::build(const SampleBuffer &buffer, qint64 fromUs, qint64 toUs, int widthPx,
                                                 qint64 originUs, double scale, double offset)
{
    Result r;
    if (toUs < fromUs || buffer.isEmpty())
        return r;
    // width - 1 buckets of <= 2 points, plus two edge points; a plot narrower than two
    // pixels gets one bucket and no edge points.
    const bool edges = widthPx >= 2;
    const int buckets = edges ? widthPx - 1 : 1;
    const QList<TrendSample> inside = Decimator::minMax(buffer, fromUs, toUs, buckets);
    const auto map = [&](const TrendSample &s) {
        // Subtract in integers first: doubles lose µs beyond ~285 years but not differences.
        return QPointF(static_cast<double>(s.timeUs - originUs) * 1e-6, s.value * scale + offset);
    };
    r.points.reserve(inside.size() + 2);
    const qsizetype before = buffer.lowerBound(fromUs) - 1;
    if (edges && before >= 0 && !std::isnan(buffer.valueAt(before)))
        r.points.append(map(buffer.at(before)));
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
    for (const TrendSample &s : inside) {
        const QPointF p = map(s);
        lo = std::min(lo, p.y());
        hi = std::max(hi, p.y());
        r.points.append(p);
    }
    const qsizetype after = buffer.upperBound(toUs);
    if (edges && after < buffer.size() && !std::isnan(buffer.valueAt(after)))
        r.points.append(map(buffer.at(after)));
    if (!inside.isEmpty()) {
        r.yMin = lo;
        r.yMax = hi;
    }
    return r;
}

} // namespace dd
