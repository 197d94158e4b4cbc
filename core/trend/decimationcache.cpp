#include "core/trend/decimationcache.h"

#include "core/trend/samplebuffer.h"

#include <algorithm>
#include <vector>

namespace dd {

void DecimationCache::clear()
{
    m_buckets.clear();
    m_buffer = nullptr;
    m_generation = 0;
    m_bucketUs = 0;
    m_firstBucket = 0;
}

QList<TrendSample> DecimationCache::minMax(const SampleBuffer &buffer, qint64 fromUs, qint64 toUs, qint64 bucketUs)
{
    m_lastComputed = 0;
    if (toUs < fromUs || bucketUs < 1 || buffer.isEmpty())
        return {};
    if (m_buffer != &buffer || m_generation != buffer.generation() || m_bucketUs != bucketUs) {
        clear();
        m_buffer = &buffer;
        m_generation = buffer.generation();
        m_bucketUs = bucketUs;
    }
    const qint64 bw = bucketUs;
    const qint64 firstBucket = Decimator::alignedBucket(fromUs, bw);
    const qint64 lastBucket = Decimator::alignedBucket(toUs, bw);
    // The buckets that can come from the cache: wholly inside the window, finished (a sample
    // after the bucket is in: bucket k ends at (k + 1) × bw <= the newest time), none of
    // their samples evicted (they start after the oldest sample kept).
    qint64 lo = firstBucket * bw == fromUs ? firstBucket : firstBucket + 1;
    qint64 hi = (lastBucket + 1) * bw - 1 == toUs ? lastBucket : lastBucket - 1;
    hi = std::min(hi, Decimator::alignedBucket(buffer.lastTimeUs(), bw) - 1);
    if (buffer.droppedCount() > 0)
        lo = std::max(lo, Decimator::alignedBucket(buffer.firstTimeUs(), bw) + 1);
    if (lo > hi) {
        m_buckets.clear();
        m_lastComputed = lastBucket - firstBucket + 1;
        return Decimator::minMaxAligned(buffer, fromUs, toUs, bw);
    }

    // Keep what overlaps [lo, hi], compute what is missing at either end.
    if (!m_buckets.empty()) {
        const qint64 cachedLast = m_firstBucket + static_cast<qint64>(m_buckets.size()) - 1;
        if (cachedLast < lo || m_firstBucket > hi) {
            m_buckets.clear();
        } else {
            while (m_firstBucket < lo) {
                m_buckets.pop_front();
                ++m_firstBucket;
            }
            const qint64 keep = hi - m_firstBucket + 1;
            while (static_cast<qint64>(m_buckets.size()) > keep)
                m_buckets.pop_back();
        }
    }
    if (m_buckets.empty()) {
        m_firstBucket = lo;
        fill(buffer, lo, hi, false);
    } else {
        if (m_firstBucket > lo)
            fill(buffer, lo, m_firstBucket - 1, true);
        const qint64 cachedLast = m_firstBucket + static_cast<qint64>(m_buckets.size()) - 1;
        if (cachedLast < hi)
            fill(buffer, cachedLast + 1, hi, false);
    }
    m_lastComputed += (lo - firstBucket) + (lastBucket - hi);

    QList<TrendSample> out;
    if (lo * bw > fromUs)
        out = Decimator::minMaxAligned(buffer, fromUs, lo * bw - 1, bw);
    out.reserve(out.size() + 2 * static_cast<qsizetype>(m_buckets.size()) + 4);
    for (const Bucket &b : m_buckets) {
        if (b.count >= 1)
            out.append(b.first);
        if (b.count == 2)
            out.append(b.second);
    }
    if ((hi + 1) * bw <= toUs)
        out.append(Decimator::minMaxAligned(buffer, (hi + 1) * bw, toUs, bw));
    return out;
}

void DecimationCache::fill(const SampleBuffer &buffer, qint64 fromBucket, qint64 toBucket, bool atFront)
{
    const qint64 bw = m_bucketUs;
    std::vector<Bucket> made(static_cast<size_t>(toBucket - fromBucket + 1));
    const QList<TrendSample> points = Decimator::minMaxAligned(buffer, fromBucket * bw, (toBucket + 1) * bw - 1, bw);
    for (const TrendSample &p : points) {
        Bucket &b = made[static_cast<size_t>(Decimator::alignedBucket(p.timeUs, bw) - fromBucket)];
        (b.count == 0 ? b.first : b.second) = p;
        ++b.count;
    }
    m_lastComputed += toBucket - fromBucket + 1;
    if (atFront) {
        m_buckets.insert(m_buckets.begin(), made.cbegin(), made.cend());
        m_firstBucket = fromBucket;
    } else {
        m_buckets.insert(m_buckets.end(), made.cbegin(), made.cend());
    }
}

} // namespace dd
