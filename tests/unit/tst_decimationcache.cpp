#include <QtTest>

#include "core/trend/decimationcache.h"
#include "core/trend/decimator.h"
#include "core/trend/samplebuffer.h"
#include "core/trend/trendplotbuilder.h"

#include <algorithm>
#include <cmath>
#include <limits>

using namespace dd;

namespace {

using CacheSamples = QList<TrendSample>;
constexpr double Gap = std::numeric_limits<double>::quiet_NaN();

// Noisy values with ties, a spike now and then, and gap markers (NaN).
double noisy(QRandomGenerator &rng)
{
    if (rng.bounded(200) == 0)
        return Gap;
    if (rng.bounded(500) == 0)
        return rng.bounded(2) ? 1e6 : -1e6;
    return double(rng.bounded(50));
}

bool sameSamples(const CacheSamples &a, const CacheSamples &b)
{
    if (a.size() != b.size())
        return false;
    for (qsizetype i = 0; i < a.size(); ++i) {
        if (a.at(i).timeUs != b.at(i).timeUs || a.at(i).value != b.at(i).value)
            return false;
    }
    return true;
}

bool samePoints(const QList<QPointF> &a, const QList<QPointF> &b)
{
    if (a.size() != b.size())
        return false;
    for (qsizetype i = 0; i < a.size(); ++i) {
        if (a.at(i).x() != b.at(i).x())
            return false;
        const bool nanA = std::isnan(a.at(i).y());
        if (nanA != std::isnan(b.at(i).y()) || (!nanA && a.at(i).y() != b.at(i).y()))
            return false;
    }
    return true;
}

} // namespace

// The trend's live update decimates through DecimationCache: finished aligned buckets are
// kept, only the window's edges are computed again. It must give exactly what a
// decimation from scratch gives (the envelope, the gaps), whatever the window does.
class TestDecimationCache : public QObject
{
    Q_OBJECT
private slots:
    void alignedBucketsFollowAbsoluteTime()
    {
        SampleBuffer b;
        for (int t = 0; t < 20; ++t)
            b.append(t, t % 7);
        // Buckets of 5 µs: [0,4] [5,9] [10,14] [15,19]; the window [3, 16] cuts the first
        // and the last: [3,4] -> 3@3, 4@4; [5,9] -> max 6@6, min 0@7 (in time order);
        // [10,14] -> 6@13, 0@14; [15,16] -> 1@15, 2@16.
        const CacheSamples out = Decimator::minMaxAligned(b, 3, 16, 5);
        QCOMPARE(out, (CacheSamples{{3, 3}, {4, 4}, {6, 6}, {7, 0}, {13, 6}, {14, 0}, {15, 1}, {16, 2}}));
        QCOMPARE(Decimator::alignedBucket(-1, 5), -1);
        QCOMPARE(Decimator::alignedBucket(-5, 5), -1);
        QCOMPARE(Decimator::alignedBucket(-6, 5), -2);
        QCOMPARE(Decimator::alignedBucket(9, 5), 1);
        QVERIFY(Decimator::minMaxAligned(b, 16, 3, 5).isEmpty());
        QVERIFY(Decimator::minMaxAligned(b, 0, 19, 0).isEmpty());
    }

    // A live window sliding over a growing recording, with gaps, ties and spikes: the cache
    // gives the from-scratch result on every update and computes only the edge buckets.
    void slidingWindowMatchesAFreshDecimation()
    {
        QRandomGenerator rng(10);
        SampleBuffer b;
        DecimationCache cache;
        const qint64 window = 30000; // 30 ms at 1 µs ticks ~ a 30 s window at 1 ms ticks
        const qint64 bucket = TrendPlotBuilder::bucketUs(0, window, 890);
        qint64 t = 0;
        for (int i = 0; i < 60000; ++i) {
            t += 1 + rng.bounded(2);
            b.append(t, noisy(rng));
        }
        int updates = 0;
        for (int step = 0; step < 300; ++step) {
            const int more = 1 + int(rng.bounded(8));
            for (int i = 0; i < more; ++i) {
                t += rng.bounded(3); // equal times too
                b.append(t, noisy(rng));
            }
            const qint64 to = b.lastTimeUs();
            const qint64 from = to - window;
            const CacheSamples cached = cache.minMax(b, from, to, bucket);
            const CacheSamples fresh = Decimator::minMaxAligned(b, from, to, bucket);
            QVERIFY2(sameSamples(cached, fresh), qPrintable(QStringLiteral("update %1").arg(step)));
            if (step > 0) {
                // The partial first and last bucket, and the one or two that just finished.
                QVERIFY2(cache.lastComputedBuckets() <= 4, qPrintable(QString::number(cache.lastComputedBuckets())));
                ++updates;
            }
        }
        QCOMPARE(updates, 299);
        QVERIFY(cache.cachedBuckets() > 800);
    }

    // Zoom, pan back and forth, a ring that evicts, a clear, another bucket width: still the
    // from-scratch result.
    void panZoomEvictionAndClearMatchAFreshDecimation()
    {
        QRandomGenerator rng(11);
        SampleBuffer b(20000); // a ring: evicts the oldest
        DecimationCache cache;
        qint64 t = 0;
        const auto grow = [&](int n) {
            for (int i = 0; i < n; ++i) {
                t += rng.bounded(4);
                b.append(t, noisy(rng));
            }
        };
        grow(30000);
        QVERIFY(b.droppedCount() > 0);
        for (int round = 0; round < 200; ++round) {
            const qint64 span = 1 + rng.bounded(qint64(t));
            const qint64 from = b.firstTimeUs() - 50 + rng.bounded(qint64(t - b.firstTimeUs() + 100));
            const qint64 to = from + span;
            const int width = 3 + int(rng.bounded(1500));
            const qint64 bucket = round % 3 == 0 ? TrendPlotBuilder::bucketUs(from, to, width) : 1 + rng.bounded(500);
            QVERIFY(sameSamples(cache.minMax(b, from, to, bucket), Decimator::minMaxAligned(b, from, to, bucket)));
            // The same again (a frozen view), then panned by a little.
            QVERIFY(sameSamples(cache.minMax(b, from, to, bucket), Decimator::minMaxAligned(b, from, to, bucket)));
            const qint64 shift = rng.bounded(2 * bucket + 1) - bucket;
            QVERIFY(sameSamples(cache.minMax(b, from + shift, to + shift, bucket),
                                Decimator::minMaxAligned(b, from + shift, to + shift, bucket)));
            if (round % 10 == 0)
                grow(int(rng.bounded(3000))); // evicts the oldest buckets' samples
            if (round == 100) {
                b.clear(); // a new recording: what the cache held is gone
                t = 1000;
                grow(25000);
            }
        }
    }

    // A zoomed (frozen) view of the oldest part of a full ring while the recording goes on:
    // each new sample evicts the oldest, so the buckets at the view's left lose samples and
    // must not come from the cache.
    void evictedBucketsAreComputedAgain()
    {
        QRandomGenerator rng(12);
        SampleBuffer b(5000);
        DecimationCache cache;
        qint64 t = 0;
        for (int i = 0; i < 5000; ++i)
            b.append(t += 10, double(rng.bounded(1000)));
        const qint64 from = 0;
        const qint64 to = 40000;
        for (int step = 0; step < 60; ++step) {
            QVERIFY2(sameSamples(cache.minMax(b, from, to, 300), Decimator::minMaxAligned(b, from, to, 300)),
                     qPrintable(QStringLiteral("step %1").arg(step)));
            for (int i = 0; i < 40; ++i)
                b.append(t += 10, double(rng.bounded(1000)));
        }
    }

    // Through the plot builder: with and without the cache the same points, gap breaks
    // included, and a gap is a break (NaN point), never a ramp.
    void plotPointsAndGapsAreTheSameWithTheCache()
    {
        SampleBuffer b;
        DecimationCache cache;
        qint64 t = 0;
        for (int i = 0; i < 100000; ++i) {
            t += 1000; // 1 kHz
            // Silent from 40 s to 47 s: a gap marker at its start, as the recorder writes it.
            if (t > 40000000 && t < 47000000)
                continue;
            b.append(t, t == 40000000 ? Gap : std::sin(double(i) * 0.01) * 100.0);
        }
        const qint64 window = 30000000;
        int withGap = 0;
        for (qint64 to = 35000000; to <= b.lastTimeUs(); to += 250000) {
            const auto cached = TrendPlotBuilder::build(b, to - window, to, 890, 0, 2.0, 1.0, &cache);
            const auto fresh = TrendPlotBuilder::build(b, to - window, to, 890, 0, 2.0, 1.0);
            QVERIFY(samePoints(cached.points, fresh.points));
            QCOMPARE(cached.yMin, fresh.yMin);
            QCOMPARE(cached.yMax, fresh.yMax);
            QVERIFY(cached.points.size() <= 2 * 890 + 1);
            const auto breakAt = std::find_if(cached.points.cbegin(), cached.points.cend(),
                                              [](const QPointF &p) { return std::isnan(p.y()); });
            if (to - window < 40000000 && to > 47000000) {
                // The window spans the gap: one break, and no point inside the silent time.
                QVERIFY(breakAt != cached.points.cend());
                ++withGap;
                QCOMPARE(std::count_if(cached.points.cbegin(), cached.points.cend(),
                                       [](const QPointF &p) { return std::isnan(p.y()); }),
                         1);
                for (const QPointF &p : cached.points)
                    QVERIFY(std::isnan(p.y()) || p.x() <= 40.0 || p.x() >= 47.0);
                QVERIFY(breakAt != cached.points.cbegin() && (breakAt - 1)->x() <= 40.0 && breakAt->x() >= 47.0);
            }
        }
        QVERIFY(withGap > 50);
    }
};

QTEST_APPLESS_MAIN(TestDecimationCache)
#include "tst_decimationcache.moc"
