#include "core/tuning/capturedata.h"

#include <algorithm>

namespace dd {

IntervalStats IntervalStats::of(const QVector<double> &times)
{
    IntervalStats s;
    if (times.size() < 2)
        return s;
    QVector<double> d;
    d.reserve(times.size() - 1);
    for (int i = 1; i < times.size(); ++i)
        d.append(times.at(i) - times.at(i - 1));
    s.count = int(d.size());
    double sum = 0.0;
    for (double v : d)
        sum += v;
    s.mean = sum / double(d.size());
    s.min = *std::min_element(d.begin(), d.end());
    s.max = *std::max_element(d.begin(), d.end());
    std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
    s.median = d.at(d.size() / 2);
    return s;
}

QList<CaptureGap> CaptureGap::of(const QVector<double> &times)
{
    QList<CaptureGap> gaps;
    const IntervalStats s = IntervalStats::of(times);
    if (s.count < 2 || s.median <= 0.0)
        return gaps;
    for (int i = 1; i < times.size(); ++i)
        if (times.at(i) - times.at(i - 1) > 3.0 * s.median)
            gaps.append({times.at(i - 1), times.at(i)});
    return gaps;
}

} // namespace dd
