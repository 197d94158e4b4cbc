#pragma once

#include "core/trend/trendsample.h"

#include <QList>

namespace dd {

class SampleBuffer;

// Min/max decimation for plotting: the time window [fromUs, toUs] (both ends included) is
// cut into `buckets` buckets of equal duration (one per pixel column); of the samples in
// each bucket only the one with the smallest and the one with the largest value are kept,
// in their time order. A bucket therefore yields 0, 1 (one sample, or the minimum and the
// maximum are the same sample) or 2 points, so the result never has more than 2 × buckets
// points, and every peak and trough in the window survives.
//
// Exact rules (tests rely on them):
// - sample time t belongs to bucket floor((t - fromUs) × buckets / (toUs - fromUs + 1));
// - on equal values the earliest sample is the minimum / maximum;
// - NaN values are skipped; samples outside the window are ignored;
// - buckets < 1 counts as 1; toUs < fromUs gives an empty result.
// A bucket with at most two samples keeps them all, so when the data is sparser than two
// samples per bucket the output equals the input window: decimation is lossless there.
// Pure functions. Over a list: a scan, O(samples in the window). Over a SampleBuffer,
// two strategies with exactly the same result: Scan, or Summaries (per non-empty bucket a
// galloping search from the bucket's start, O(log samples per bucket) in memory just
// read, plus SampleBuffer::extremes() over the block summaries, so a 10-minute window at
// 1 kHz costs about as much as a few seconds of raw samples). Auto scans when buckets
// hold fewer than ~256 samples on average, where the summaries do not pay off.
class Decimator
{
public:
    enum class Strategy { Auto, Scan, Summaries };

    static QList<TrendSample> minMax(const SampleBuffer &buffer, qint64 fromUs, qint64 toUs, int buckets,
                                     Strategy strategy = Strategy::Auto);
    // The same over samples sorted by time (non-decreasing).
    static QList<TrendSample> minMax(const QList<TrendSample> &sorted, qint64 fromUs, qint64 toUs, int buckets);

    // Buckets anchored to absolute time instead of the window: bucket k holds the times
    // [k × bucketUs, (k + 1) × bucketUs), whatever the window. Only samples in
    // [fromUs, toUs] are taken, so the first and the last bucket may be partial. The same
    // rules otherwise (earliest on equal values, NaN skipped, ≤ 2 points a bucket). As the
    // window slides, a bucket's points do not change once the buffer holds a sample after
    // it (DecimationCache keeps them). bucketUs < 1 or toUs < fromUs: empty.
    static QList<TrendSample> minMaxAligned(const SampleBuffer &buffer, qint64 fromUs, qint64 toUs, qint64 bucketUs,
                                            Strategy strategy = Strategy::Auto);
    // floor(timeUs / bucketUs): the aligned bucket of a time (bucketUs >= 1).
    static qint64 alignedBucket(qint64 timeUs, qint64 bucketUs);

    // The bucket of timeUs, or -1 when it lies outside the window.
    static int bucketOf(qint64 timeUs, qint64 fromUs, qint64 toUs, int buckets);
};

} // namespace dd
