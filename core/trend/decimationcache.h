#pragma once

#include "core/trend/decimator.h"

#include <deque>

namespace dd {

class SampleBuffer;

// Remembers the min/max points of finished aligned buckets (Decimator::minMaxAligned) of
// one channel's buffer, so a live plot that slides its window by one sample recomputes
// only the buckets at its two edges instead of the whole window.
//
// minMax() returns exactly Decimator::minMaxAligned(buffer, fromUs, toUs, bucketUs) (tests
// compare them). A bucket is taken from the cache only when nothing can change it any more:
// - it lies wholly inside [fromUs, toUs] (the partial edge buckets are computed each time);
// - the buffer holds a sample after it (samples only come in time order, so none can join);
// - no sample of it was evicted (it starts after the oldest sample kept, or none was
//   dropped);
// - the buffer is the one and in the state it was computed from (SampleBuffer::generation:
//   clear() and setCapacity() empty the cache), with the same bucket width.
// Gap markers (NaN) are skipped as by the Decimator; the plot breaks the line between
// points from the buffer's gap times (TrendPlotBuilder), so gaps stay gaps.
// The cache holds the buckets of the last window only (memory ∝ the plot's width).
class DecimationCache
{
public:
    QList<TrendSample> minMax(const SampleBuffer &buffer, qint64 fromUs, qint64 toUs, qint64 bucketUs);

    void clear();
    // Buckets computed by the last minMax() call (the rest came from the cache); for tests
    // and the benchmark.
    qint64 lastComputedBuckets() const { return m_lastComputed; }
    qsizetype cachedBuckets() const { return static_cast<qsizetype>(m_buckets.size()); }

private:
    struct Bucket
    {
        TrendSample first;
        TrendSample second;
        quint8 count = 0; // 0, 1 or 2 points
    };
    // Buckets [fromBucket, toBucket] computed and appended to m_buckets (back) or put in
    // front of it.
    void fill(const SampleBuffer &buffer, qint64 fromBucket, qint64 toBucket, bool atFront);

    const SampleBuffer *m_buffer = nullptr;
    quint64 m_generation = 0;
    qint64 m_bucketUs = 0;
    qint64 m_firstBucket = 0; // bucket number of m_buckets.front()
    std::deque<Bucket> m_buckets;
    qint64 m_lastComputed = 0;
};

} // namespace dd
