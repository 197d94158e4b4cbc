#include "core/trend/decimator.h"

#include "core/trend/samplebuffer.h"

#include <algorithm>
#include <cmath>

namespace dd {

namespace {

// Window arithmetic in µs ticks: the window holds span = toUs - fromUs + 1 ticks and tick
// offset d belongs to bucket d × n / span. Products stay far below 2^63 for any realistic
// window (a year in µs × 100,000 buckets is 3 × 10^18).
struct Window
{
    qint64 from;
    qint64 span;
    qint64 n;

    qint64 bucketOf(qint64 t) const { return (t - from) * n / span; }
    // First time that belongs to bucket k + 1: from + ceil((k + 1) × span / n).
    qint64 endOf(qint64 k) const { return from + ((k + 1) * span + n - 1) / n; }
};

// Get: qsizetype -> TrendSample. Scans indices [begin, end), all inside the window.
template <typename Get>
QList<TrendSample> decimate(const Window &w, qsizetype begin, qsizetype end, Get get)
{
    QList<TrendSample> out;
    if (begin >= end)
        return out;
    out.reserve(std::min<qsizetype>(end - begin, 2 * w.n));
    qsizetype i = begin;
    while (i < end) {
        const qint64 bucket = w.bucketOf(get(i).timeUs);
        const qint64 bucketEnd = w.endOf(bucket);
        bool any = false;
        TrendSample lo;
        TrendSample hi;
        qsizetype loIdx = 0;
        qsizetype hiIdx = 0;
        for (; i < end; ++i) {
            const TrendSample s = get(i);
            if (s.timeUs >= bucketEnd)
                break;
            if (std::isnan(s.value))
                continue;
            if (!any) {
                lo = hi = s;
                loIdx = hiIdx = i;
                any = true;
            } else if (s.value < lo.value) {
                lo = s;
                loIdx = i;
            } else if (s.value > hi.value) {
                hi = s;
                hiIdx = i;
            }
        }
        if (!any)
            continue;
        if (loIdx == hiIdx) {
            out.append(lo);
        } else if (loIdx < hiIdx) {
            out.append(lo);
            out.append(hi);
        } else {
            out.append(hi);
            out.append(lo);
        }
    }
    return out;
}

bool makeWindow(qint64 fromUs, qint64 toUs, int buckets, Window *w)
{
    if (toUs < fromUs)
        return false;
    *w = Window{fromUs, toUs - fromUs + 1, std::max(1, buckets)};
    return true;
}

// The samples with index in [i, end), all at or after w.from, decimated into w's buckets.
QList<TrendSample> decimateBuffer(const SampleBuffer &buffer, const Window &w, qsizetype i, qsizetype end,
                                  Decimator::Strategy strategy)
{
    using Strategy = Decimator::Strategy;
    if (strategy == Strategy::Auto) {
        // Measured (docs/performance.md): summaries win from a few hundred samples per bucket.
        strategy = end - i < w.n * 4 * SampleBuffer::BlockSize ? Strategy::Scan : Strategy::Summaries;
    }
    if (strategy == Strategy::Scan)
        return decimate(w, i, end, [&buffer](qsizetype k) { return buffer.at(k); });

    // Bucket by bucket: its index range by binary search, its extremes from the buffer's
    // block summaries. Same result as the scan, without reading every sample.
    QList<TrendSample> out;
    if (i >= end)
        return out;
    out.reserve(std::min<qsizetype>(end - i, 2 * w.n));
    while (i < end) {
        const qint64 bucketEnd = w.endOf(w.bucketOf(buffer.timeAt(i)));
        // The first sample at or after bucketEnd, galloping from i: the search stays in the
        // memory just read (a binary search over the whole buffer misses the cache on
        // every step: ~2 µs per bucket on 600k samples).
        qsizetype lo = i;
        qsizetype step = 1;
        qsizetype hi = i + 1;
        while (hi < end && buffer.timeAt(hi) < bucketEnd) {
            lo = hi;
            step *= 2;
            hi = std::min(end, hi + step);
        }
        while (lo < hi) { // first index in [lo, hi] with time >= bucketEnd (hi: end or such)
            const qsizetype mid = lo + (hi - lo) / 2;
            if (buffer.timeAt(mid) < bucketEnd)
                lo = mid + 1;
            else
                hi = mid;
        }
        const qsizetype j = lo;
        const SampleBuffer::Extremes e = buffer.extremes(i, j);
        if (e.minIndex >= 0) {
            if (e.minIndex == e.maxIndex) {
                out.append(buffer.at(e.minIndex));
            } else {
                out.append(buffer.at(std::min(e.minIndex, e.maxIndex)));
                out.append(buffer.at(std::max(e.minIndex, e.maxIndex)));
            }
        }
        i = j;
    }
    return out;
}

} // namespace

QList<TrendSample> Decimator::minMax(const SampleBuffer &buffer, qint64 fromUs, qint64 toUs, int buckets,
                                     Strategy strategy)
{
    Window w{};
    if (!makeWindow(fromUs, toUs, buckets, &w))
        return {};
    return decimateBuffer(buffer, w, buffer.lowerBound(fromUs), buffer.upperBound(toUs), strategy);
}

qint64 Decimator::alignedBucket(qint64 timeUs, qint64 bucketUs)
{
    const qint64 q = timeUs / bucketUs;
    return (timeUs % bucketUs != 0 && timeUs < 0) ? q - 1 : q; // floor
}

QList<TrendSample> Decimator::minMaxAligned(const SampleBuffer &buffer, qint64 fromUs, qint64 toUs, qint64 bucketUs,
                                            Strategy strategy)
{
    if (toUs < fromUs || bucketUs < 1)
        return {};
    // Aligned buckets are a window that starts on the first bucket's start and spans whole
    // buckets: there (t - from) × n / span is (t - from) / bucketUs. Only the samples in
    // [fromUs, toUs] are taken.
    const qint64 first = alignedBucket(fromUs, bucketUs);
    const qint64 count = alignedBucket(toUs, bucketUs) - first + 1;
    const Window w{first * bucketUs, count * bucketUs, count};
    return decimateBuffer(buffer, w, buffer.lowerBound(fromUs), buffer.upperBound(toUs), strategy);
}

QList<TrendSample> Decimator::minMax(const QList<TrendSample> &sorted, qint64 fromUs, qint64 toUs, int buckets)
{
    Window w{};
    if (!makeWindow(fromUs, toUs, buckets, &w))
        return {};
    const auto byTime = [](const TrendSample &s, qint64 t) { return s.timeUs < t; };
    const auto b = std::lower_bound(sorted.cbegin(), sorted.cend(), fromUs, byTime);
    const auto e = std::upper_bound(sorted.cbegin(), sorted.cend(), toUs,
                                    [](qint64 t, const TrendSample &s) { return t < s.timeUs; });
    return decimate(w, b - sorted.cbegin(), e - sorted.cbegin(), [&sorted](qsizetype i) { return sorted.at(i); });
}

int Decimator::bucketOf(qint64 timeUs, qint64 fromUs, qint64 toUs, int buckets)
{
    Window w{};
    if (!makeWindow(fromUs, toUs, buckets, &w) || timeUs < fromUs || timeUs > toUs)
        return -1;
    return static_cast<int>(w.bucketOf(timeUs));
}

} // namespace dd
