#pragma once

#include "core/trend/trendsample.h"

#include <QList>
#include <deque>
#include <optional>
#include <vector>

namespace dd {

// The time series of one channel: samples in non-decreasing time order, bounded in memory.
//
// Memory bound: at most capacity() samples are kept, 16.5 bytes each (a qint64 time and a
// double value in two arrays, plus the block summaries below). The default,
// DefaultCapacity = 600,000 samples, is ten minutes at 1 kHz: 9.9 MB per channel, 79 MB
// for 8 channels at 1 kHz × 10 min (the worst case the trend view offers). Storage grows with the recording (a short one costs
// little) and never beyond the capacity. Past the capacity the buffer is a ring: each new
// sample evicts the oldest one, and droppedCount() says how many were evicted, so a
// long recording keeps its most recent capacity() samples.
//
// A sample older than the newest one is rejected (append() returns false and
// rejectedCount() counts it): lookups rely on the order. Equal times are allowed.
// Lookups by time are binary searches, O(log n).
//
// For fast decimation of long windows the buffer also keeps, per block of BlockSize
// consecutive samples, the block's smallest and largest sample (0.5 byte per sample):
// extremes() over a range reads whole blocks from these summaries and only scans the
// partial blocks at its ends, O(BlockSize + n / BlockSize).
//
// Gaps: a NaN value marks a gap (the recording lost the drive at that time: link lost,
// drive silent, recording stopped). The plot breaks the line there and the CSV writes
// "nan"; lookups and extremes skip it. The times of the NaN samples kept are indexed
// (gapTimes()) so a plot finds them without scanning. Not thread-safe.
class SampleBuffer
{
public:
    static constexpr qsizetype DefaultCapacity = 600000;
    static constexpr qsizetype BlockSize = 64;

    // Indices of the smallest and the largest value in a range (the earliest one on
    // equal values; NaN values are skipped); -1 when the range has no number.
    struct Extremes
    {
        qsizetype minIndex = -1;
        qsizetype maxIndex = -1;
    };

    explicit SampleBuffer(qsizetype capacity = DefaultCapacity);

    bool append(qint64 timeUs, double value);
    void clear(); // also resets the counters and frees the storage

    qsizetype size() const { return m_size; }
    bool isEmpty() const { return m_size == 0; }
    qsizetype capacity() const { return m_capacity; }
    // Changes the bound; when shrinking, the newest `capacity` samples are kept (the
    // others count as dropped). A capacity below 1 is taken as 1.
    void setCapacity(qsizetype capacity);
    quint64 droppedCount() const { return m_dropped; }
    quint64 rejectedCount() const { return m_rejected; }
    // A stamp unique in the process, new on construction, clear() and setCapacity(): where
    // it changed, what was computed from the buffer's samples (DecimationCache) no longer
    // holds. Appending and evicting the oldest sample keep it (droppedCount() tells those).
    quint64 generation() const { return m_generation; }
    // Bytes held by the sample storage (allocated, not just used).
    qsizetype memoryBytes() const;

    // Logical index: 0 is the oldest sample kept, size() - 1 the newest.
    qint64 timeAt(qsizetype i) const { return m_times[physical(i)]; }
    double valueAt(qsizetype i) const { return m_values[physical(i)]; }
    TrendSample at(qsizetype i) const { return {timeAt(i), valueAt(i)}; }
    qint64 firstTimeUs() const { return timeAt(0); }         // only when !isEmpty()
    qint64 lastTimeUs() const { return timeAt(m_size - 1); } // only when !isEmpty()

    // First index whose time is >= timeUs (size() if none).
    qsizetype lowerBound(qint64 timeUs) const;
    // First index whose time is > timeUs (size() if none).
    qsizetype upperBound(qint64 timeUs) const;
    // The sample nearest in time (the earlier one on a tie); nullopt when empty.
    std::optional<TrendSample> nearest(qint64 timeUs) const;
    // Copies of the samples with fromUs <= time <= toUs, oldest first.
    QList<TrendSample> samples(qint64 fromUs, qint64 toUs) const;
    QList<TrendSample> samples() const;
    // Extremes of the samples with index in [begin, end).
    Extremes extremes(qsizetype begin, qsizetype end) const;

    // Times of the gap markers (NaN samples) with fromUs <= time <= toUs, oldest first.
    std::vector<qint64> gapTimes(qint64 fromUs, qint64 toUs) const;
    qsizetype gapCount() const { return static_cast<qsizetype>(m_gaps.size()); }
    // The value the plotted line has at timeUs: linear between the samples either side
    // (the sample itself at its exact time); nullopt outside the recording and inside a gap
    // (either neighbour is a gap marker).
    std::optional<double> lineValueAt(qint64 timeUs) const;

private:
    struct Block
    {
        double minValue = 0.0;
        double maxValue = 0.0;
        qint64 minSeq = -1; // -1: no number in the block yet
        qint64 maxSeq = -1;
    };
    // Samples are numbered by seq since clear(); index 0 is seq m_dropped.
    void summarize(qint64 seq, double value);
    void rebuildSummaries();

    qsizetype physical(qsizetype i) const
    {
        const qsizetype p = m_head + i;
        return p >= m_capacity ? p - m_capacity : p;
    }

    std::vector<qint64> m_times;
    std::vector<double> m_values;
    std::vector<Block> m_blocks; // ring: block b at b % blockSlots()
    std::deque<qint64> m_gaps;   // times of the NaN samples kept, oldest first
    void rebuildGaps();
    qsizetype blockSlots() const { return m_capacity / BlockSize + 2; }
    qsizetype m_capacity;
    qsizetype m_head = 0; // physical index of the oldest sample (0 until the ring wraps)
    qsizetype m_size = 0;
    quint64 m_dropped = 0;
    quint64 m_rejected = 0;
    quint64 m_generation;
};

} // namespace dd
