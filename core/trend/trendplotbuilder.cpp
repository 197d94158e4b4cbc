#include "core/trend/trendplotbuilder.h"

#include "core/trend/decimationcache.h"
#include "core/trend/decimator.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dd {

qint64 TrendPlotBuilder::bucketUs(qint64 fromUs, qint64 toUs, int widthPx)
{
    // A window of span ticks starting anywhere touches at most floor((span - 1) / w) + 2
    // buckets of width w; with w >= span / (buckets - 1) that is at most `buckets`.
    const qint64 span = std::max<qint64>(1, toUs - fromUs + 1);
    const qint64 buckets = std::max(3, widthPx) - 1;
    return std::max<qint64>(1, (span + buckets - 2) / (buckets - 1));
}

TrendPlotBuilder::Result TrendPlotBuilder::build(const SampleBuffer &buffer, qint64 fromUs, qint64 toUs, int widthPx,
                                                 qint64 originUs, double scale, double offset, DecimationCache *cache)
{
    Result r;
    if (toUs < fromUs || buffer.isEmpty())
        return r;
    // width - 1 buckets of <= 2 points, plus two edge points; a plot narrower than two
    // pixels gets one bucket and no edge points.
    const bool edges = widthPx >= 2;
    QList<TrendSample> inside;
    if (widthPx < 3) {
        inside = Decimator::minMax(buffer, fromUs, toUs, 1);
    } else {
        const qint64 width = bucketUs(fromUs, toUs, widthPx);
        inside = cache ? cache->minMax(buffer, fromUs, toUs, width)
                       : Decimator::minMaxAligned(buffer, fromUs, toUs, width);
    }
    const auto map = [&](const TrendSample &s) {
        // Subtract in integers first: doubles lose µs beyond ~285 years but not differences.
        return QPointF(static_cast<double>(s.timeUs - originUs) * 1e-6, s.value * scale + offset);
    };
    QList<TrendSample> line;
    line.reserve(inside.size() + 2);
    const qsizetype before = buffer.lowerBound(fromUs) - 1;
    if (edges && before >= 0 && !std::isnan(buffer.valueAt(before)))
        line.append(buffer.at(before));
    line.append(inside);
    const qsizetype after = buffer.upperBound(toUs);
    if (edges && after < buffer.size() && !std::isnan(buffer.valueAt(after)))
        line.append(buffer.at(after));
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
    for (const TrendSample &s : inside) {
        const double y = s.value * scale + offset;
        lo = std::min(lo, y);
        hi = std::max(hi, y);
    }
    // Gap markers between the first and the last point, walked in step with the points.
    const std::vector<qint64> gaps = line.isEmpty() ? std::vector<qint64>()
                                                    : buffer.gapTimes(line.first().timeUs, line.last().timeUs);
    auto gap = gaps.cbegin();
    r.points.reserve(line.size() + static_cast<qsizetype>(gaps.size()));
    for (qsizetype i = 0; i < line.size(); ++i) {
        const qint64 t = line.at(i).timeUs;
        if (i > 0) {
            bool broken = false;
            while (gap != gaps.cend() && *gap <= t) {
                broken = broken || *gap >= line.at(i - 1).timeUs;
                ++gap;
            }
            if (broken)
                r.points.append(QPointF(static_cast<double>(t - originUs) * 1e-6, std::nan("")));
        } else {
            while (gap != gaps.cend() && *gap < t)
                ++gap;
        }
        r.points.append(map(line.at(i)));
    }
    if (!inside.isEmpty()) {
        r.yMin = lo;
        r.yMax = hi;
    }
    return r;
}

} // namespace dd
