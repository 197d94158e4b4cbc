#include "core/trend/samplebuffer.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace dd {

namespace {

quint64 nextGeneration()
{
    static std::atomic<quint64> last{0};
    return ++last;
}

} // namespace

SampleBuffer::SampleBuffer(qsizetype capacity)
    : m_capacity(std::max<qsizetype>(1, capacity))
    , m_generation(nextGeneration())
{
}

bool SampleBuffer::append(qint64 timeUs, double value)
{
    if (m_size > 0 && timeUs < lastTimeUs()) {
        ++m_rejected;
        return false;
    }
    if (m_size < m_capacity) {
        // Still growing: the ring has not wrapped, so m_head is 0 and storage is linear.
        const qsizetype have = static_cast<qsizetype>(m_times.capacity());
        if (m_size == have) {
            // Grow geometrically but never past the bound.
            const qsizetype want = std::min(m_capacity, std::max<qsizetype>(1024, have * 2));
            m_times.reserve(static_cast<size_t>(want));
            m_values.reserve(static_cast<size_t>(want));
        }
        m_times.push_back(timeUs);
        m_values.push_back(value);
        if (std::isnan(value))
            m_gaps.push_back(timeUs);
        summarize(static_cast<qint64>(m_dropped) + m_size, value);
        ++m_size;
        return true;
    }
    // Full: overwrite the oldest sample.
    if (std::isnan(m_values[static_cast<size_t>(m_head)]) && !m_gaps.empty())
        m_gaps.pop_front();
    if (std::isnan(value))
        m_gaps.push_back(timeUs);
    m_times[static_cast<size_t>(m_head)] = timeUs;
    m_values[static_cast<size_t>(m_head)] = value;
    m_head = m_head + 1 == m_capacity ? 0 : m_head + 1;
    ++m_dropped;
    summarize(static_cast<qint64>(m_dropped) + m_size - 1, value);
    return true;
}

void SampleBuffer::summarize(qint64 seq, double value)
{
    const size_t slot = static_cast<size_t>((seq / BlockSize) % blockSlots());
    if (slot >= m_blocks.size()) {
        if (slot >= m_blocks.capacity()) // grow like the samples, never past the slot count
            m_blocks.reserve(
                std::min<size_t>(static_cast<size_t>(blockSlots()), std::max<size_t>(16, 2 * m_blocks.capacity())));
        m_blocks.resize(slot + 1);
    }
    Block &b = m_blocks[slot];
    if (seq % BlockSize == 0)
        b = Block{}; // a new block reuses the slot
    if (std::isnan(value))
        return;
    if (b.minSeq < 0) {
        b = Block{value, value, seq, seq};
    } else if (value < b.minValue) {
        b.minValue = value;
        b.minSeq = seq;
    } else if (value > b.maxValue) {
        b.maxValue = value;
        b.maxSeq = seq;
    }
}

void SampleBuffer::rebuildSummaries()
{
    std::vector<Block>().swap(m_blocks);
    for (qsizetype i = 0; i < m_size; ++i) {
        const qint64 seq = static_cast<qint64>(m_dropped) + i;
        if (i == 0 && seq % BlockSize != 0) {
            // The first block is partial: start its slot fresh so stale data never mixes in.
            const size_t slot = static_cast<size_t>((seq / BlockSize) % blockSlots());
            if (slot >= m_blocks.size())
                m_blocks.resize(slot + 1);
            m_blocks[slot] = Block{};
        }
        summarize(seq, valueAt(i));
    }
}

SampleBuffer::Extremes SampleBuffer::extremes(qsizetype begin, qsizetype end) const
{
    Extremes e;
    double lo = 0.0;
    double hi = 0.0;
    // Candidates arrive in index order; strict comparisons keep the earliest on ties.
    const auto minCandidate = [&](qsizetype i, double v) {
        if (e.minIndex < 0 || v < lo) {
            e.minIndex = i;
            lo = v;
        }
    };
    const auto maxCandidate = [&](qsizetype i, double v) {
        if (e.maxIndex < 0 || v > hi) {
            e.maxIndex = i;
            hi = v;
        }
    };
    begin = std::max<qsizetype>(0, begin);
    end = std::min(end, m_size);
    const qint64 first = static_cast<qint64>(m_dropped);
    const qsizetype slotCount = blockSlots();
    qsizetype i = begin;
    while (i < end) {
        const qint64 seq = first + i;
        if (seq % BlockSize == 0 && i + BlockSize <= end) {
            // A whole block inside the range (and therefore fully kept): its summary.
            const Block &b = m_blocks[static_cast<size_t>((seq / BlockSize) % slotCount)];
            if (b.minSeq >= 0) {
                minCandidate(static_cast<qsizetype>(b.minSeq - first), b.minValue);
                maxCandidate(static_cast<qsizetype>(b.maxSeq - first), b.maxValue);
            }
            i += BlockSize;
            continue;
        }
        const double v = valueAt(i);
        if (!std::isnan(v)) {
            minCandidate(i, v);
            maxCandidate(i, v);
        }
        ++i;
    }
    return e;
}

void SampleBuffer::clear()
{
    std::vector<qint64>().swap(m_times);
    std::vector<double>().swap(m_values);
    std::vector<Block>().swap(m_blocks);
    m_gaps.clear();
    m_head = 0;
    m_size = 0;
    m_dropped = 0;
    m_rejected = 0;
    m_generation = nextGeneration();
}

void SampleBuffer::setCapacity(qsizetype capacity)
{
    capacity = std::max<qsizetype>(1, capacity);
    if (capacity == m_capacity)
        return;
    const qsizetype keep = std::min(m_size, capacity);
    const qsizetype skip = m_size - keep;
    std::vector<qint64> times;
    std::vector<double> values;
    times.reserve(static_cast<size_t>(keep));
    values.reserve(static_cast<size_t>(keep));
    for (qsizetype i = skip; i < m_size; ++i) {
        times.push_back(timeAt(i));
        values.push_back(valueAt(i));
    }
    m_times.swap(times);
    m_values.swap(values);
    m_capacity = capacity;
    m_head = 0;
    m_size = keep;
    m_dropped += static_cast<quint64>(skip);
    rebuildSummaries();
    rebuildGaps();
    m_generation = nextGeneration();
}

void SampleBuffer::rebuildGaps()
{
    m_gaps.clear();
    for (qsizetype i = 0; i < m_size; ++i)
        if (std::isnan(valueAt(i)))
            m_gaps.push_back(timeAt(i));
}

std::vector<qint64> SampleBuffer::gapTimes(qint64 fromUs, qint64 toUs) const
{
    std::vector<qint64> out;
    if (toUs < fromUs)
        return out;
    auto it = std::lower_bound(m_gaps.cbegin(), m_gaps.cend(), fromUs);
    for (; it != m_gaps.cend() && *it <= toUs; ++it)
        out.push_back(*it);
    return out;
}

std::optional<double> SampleBuffer::lineValueAt(qint64 timeUs) const
{
    if (m_size == 0 || timeUs < firstTimeUs() || timeUs > lastTimeUs())
        return std::nullopt;
    const qsizetype after = upperBound(timeUs); // first sample later than timeUs
    const qsizetype before = after - 1;         // >= 0: timeUs >= firstTimeUs()
    const double v0 = valueAt(before);
    if (timeAt(before) == timeUs || after == m_size)
        return std::isnan(v0) ? std::nullopt : std::optional<double>(v0);
    const double v1 = valueAt(after);
    if (std::isnan(v0) || std::isnan(v1))
        return std::nullopt;
    const double f = static_cast<double>(timeUs - timeAt(before)) / static_cast<double>(timeAt(after) - timeAt(before));
    return v0 + (v1 - v0) * f;
}

qsizetype SampleBuffer::memoryBytes() const
{
    return static_cast<qsizetype>(m_times.capacity() * sizeof(qint64) + m_values.capacity() * sizeof(double)
                                  + m_blocks.capacity() * sizeof(Block));
}

qsizetype SampleBuffer::lowerBound(qint64 timeUs) const
{
    qsizetype lo = 0;
    qsizetype hi = m_size;
    while (lo < hi) {
        const qsizetype mid = lo + (hi - lo) / 2;
        if (timeAt(mid) < timeUs)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

qsizetype SampleBuffer::upperBound(qint64 timeUs) const
{
    qsizetype lo = 0;
    qsizetype hi = m_size;
    while (lo < hi) {
        const qsizetype mid = lo + (hi - lo) / 2;
        if (timeAt(mid) <= timeUs)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

std::optional<TrendSample> SampleBuffer::nearest(qint64 timeUs) const
{
    if (m_size == 0)
        return std::nullopt;
    const qsizetype after = lowerBound(timeUs);
    if (after == 0)
        return at(0);
    if (after == m_size)
        return at(m_size - 1);
    // Compare distances without overflow: both are non-negative differences.
    const quint64 dBefore = static_cast<quint64>(timeUs) - static_cast<quint64>(timeAt(after - 1));
    const quint64 dAfter = static_cast<quint64>(timeAt(after)) - static_cast<quint64>(timeUs);
    return dAfter < dBefore ? at(after) : at(after - 1);
}

QList<TrendSample> SampleBuffer::samples(qint64 fromUs, qint64 toUs) const
{
    QList<TrendSample> out;
    if (toUs < fromUs)
        return out;
    const qsizetype b = lowerBound(fromUs);
    const qsizetype e = upperBound(toUs);
    out.reserve(e - b);
    for (qsizetype i = b; i < e; ++i)
        out.append(at(i));
    return out;
}

QList<TrendSample> SampleBuffer::samples() const
{
    QList<TrendSample> out;
    out.reserve(m_size);
    for (qsizetype i = 0; i < m_size; ++i)
        out.append(at(i));
    return out;
}

} // namespace dd
