#include <QtTest>

#include "core/trend/decimator.h"
#include "core/trend/samplebuffer.h"
#include "tests/support/trendsamplestring.h"

#include <QRandomGenerator>
#include <cmath>
#include <limits>

using namespace dd;

using DecimatorSamples = QList<TrendSample>;

class TestDecimator : public QObject
{
    Q_OBJECT
private:
    static SampleBuffer bufferOf(const DecimatorSamples &samples, qsizetype capacity = 1 << 20)
    {
        SampleBuffer b(capacity);
        for (const TrendSample &s : samples)
            b.append(s.timeUs, s.value);
        return b;
    }

    static DecimatorSamples noisy(int n, quint32 seed)
    {
        QRandomGenerator rng(seed);
        DecimatorSamples s;
        qint64 t = 0;
        for (int i = 0; i < n; ++i) {
            t += 1 + rng.bounded(3); // irregular spacing
            s.append({t, rng.bounded(2000.0) - 1000.0});
        }
        return s;
    }

private slots:
    void exactSmallInput()
    {
        const DecimatorSamples in{{0, 5},  {2, 1},  {4, 9},  {6, 3},   // bucket 0: min 1 then max 9
                                  {10, 4},                             // bucket 1: one sample
                                  {20, 7}, {25, 7},                    // bucket 2: flat -> earliest only
                                  {40, 2}, {41, 8}, {42, 0}, {43, 8}}; // bucket 4: max first, then min
        const DecimatorSamples expected{{2, 1}, {4, 9}, {10, 4}, {20, 7}, {41, 8}, {42, 0}};
        QCOMPARE(Decimator::minMax(in, 0, 99, 10), expected);
        const SampleBuffer b = bufferOf(in);
        QCOMPARE(Decimator::minMax(b, 0, 99, 10), expected);
        QCOMPARE(Decimator::minMax(b, 0, 99, 10, Decimator::Strategy::Scan), expected);
        QCOMPARE(Decimator::minMax(b, 0, 99, 10, Decimator::Strategy::Summaries), expected);
    }

    void bucketBoundaries()
    {
        // Window [0, 9] in 4 buckets: 10 ticks, tick d -> d * 4 / 10.
        const QList<int> expected{0, 0, 0, 1, 1, 2, 2, 2, 3, 3};
        for (int t = 0; t < 10; ++t)
            QCOMPARE(Decimator::bucketOf(t, 0, 9, 4), expected.at(t));
        QCOMPARE(Decimator::bucketOf(-1, 0, 9, 4), -1);
        QCOMPARE(Decimator::bucketOf(10, 0, 9, 4), -1);
        // One sample per tick: bucket sizes 3, 2, 3, 2 -> min/max of each.
        DecimatorSamples in;
        const QList<double> v{3, 1, 2, 5, 4, 0, 9, 9, 7, 8};
        for (int t = 0; t < 10; ++t)
            in.append({t, v.at(t)});
        const DecimatorSamples out{{0, 3}, {1, 1}, {3, 5}, {4, 4}, {5, 0}, {6, 9}, {8, 7}, {9, 8}};
        QCOMPARE(Decimator::minMax(in, 0, 9, 4), out);
        // Offset window and same layout.
        DecimatorSamples shifted;
        for (const auto &s : in)
            shifted.append({s.timeUs + 1000000, s.value});
        DecimatorSamples shiftedOut;
        for (const auto &s : out)
            shiftedOut.append({s.timeUs + 1000000, s.value});
        QCOMPARE(Decimator::minMax(shifted, 1000000, 1000009, 4), shiftedOut);
    }

    void windowClipsAndEdgeCases()
    {
        const DecimatorSamples in{{-5, 100}, {0, 1}, {5, 2}, {9, 3}, {10, -100}};
        QCOMPARE(Decimator::minMax(in, 0, 9, 1), (DecimatorSamples{{0, 1}, {9, 3}}));
        QCOMPARE(Decimator::minMax(in, 0, 9, 0), (DecimatorSamples{{0, 1}, {9, 3}})); // buckets < 1 -> 1
        QCOMPARE(Decimator::minMax(in, 0, 9, -7), (DecimatorSamples{{0, 1}, {9, 3}}));
        QCOMPARE(Decimator::minMax(in, 9, 0, 4), DecimatorSamples{});   // reversed window
        QCOMPARE(Decimator::minMax(in, 20, 30, 4), DecimatorSamples{}); // nothing inside
        QCOMPARE(Decimator::minMax(DecimatorSamples{}, 0, 9, 4), DecimatorSamples{});
        QCOMPARE(Decimator::minMax(in, 5, 5, 3), (DecimatorSamples{{5, 2}})); // one-tick window
        const SampleBuffer empty;
        QCOMPARE(Decimator::minMax(empty, 0, 9, 4), DecimatorSamples{});
    }

    void skipsNan()
    {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const DecimatorSamples in{{0, nan}, {1, 4}, {2, nan}, {3, 2}, {5, nan}, {6, nan}};
        QCOMPARE(Decimator::minMax(in, 0, 7, 2), (DecimatorSamples{{1, 4}, {3, 2}}));
    }

    void sparseDataIsLossless()
    {
        // At most two samples per bucket: the output is the input window unchanged.
        DecimatorSamples in;
        for (int i = 0; i < 500; ++i)
            in.append({i * 5, std::sin(i * 0.1)});
        QCOMPARE(Decimator::minMax(in, 0, 2499, 1000), in); // 2.5 ticks per bucket
        QCOMPARE(Decimator::minMax(in, 0, 2499, 2500), in);
    }

    void neverMoreThanTwoPointsPerBucket_data()
    {
        QTest::addColumn<int>("samples");
        QTest::addColumn<int>("buckets");
        QTest::newRow("100k into 800") << 100000 << 800;
        QTest::newRow("100k into 1") << 100000 << 1;
        QTest::newRow("10k into 3333") << 10000 << 3333;
        QTest::newRow("1k into 999") << 1000 << 999;
    }
    void neverMoreThanTwoPointsPerBucket()
    {
        QFETCH(int, samples);
        QFETCH(int, buckets);
        const DecimatorSamples in = noisy(samples, 42);
        const qint64 from = in.first().timeUs + 17;
        const qint64 to = in.last().timeUs - 23;
        const DecimatorSamples out = Decimator::minMax(in, from, to, buckets);
        QVERIFY(out.size() <= 2 * buckets);
        QList<int> perBucket(buckets, 0);
        for (qsizetype i = 0; i < out.size(); ++i) {
            const int b = Decimator::bucketOf(out.at(i).timeUs, from, to, buckets);
            QVERIFY(b >= 0);
            QVERIFY2(++perBucket[b] <= 2, qPrintable(QString::number(b)));
            if (i > 0)
                QVERIFY(out.at(i - 1).timeUs <= out.at(i).timeUs);
        }
        // Each bucket's extremes survive, and every point is an input sample.
        QList<double> lo(buckets, std::numeric_limits<double>::infinity());
        QList<double> hi(buckets, -std::numeric_limits<double>::infinity());
        for (const auto &s : in) {
            const int b = Decimator::bucketOf(s.timeUs, from, to, buckets);
            if (b < 0)
                continue;
            lo[b] = std::min(lo[b], s.value);
            hi[b] = std::max(hi[b], s.value);
        }
        QList<double> outLo(buckets, std::numeric_limits<double>::infinity());
        QList<double> outHi(buckets, -std::numeric_limits<double>::infinity());
        for (const auto &s : out) {
            const int b = Decimator::bucketOf(s.timeUs, from, to, buckets);
            outLo[b] = std::min(outLo[b], s.value);
            outHi[b] = std::max(outHi[b], s.value);
            const auto it = std::lower_bound(in.cbegin(), in.cend(), s.timeUs,
                                             [](const TrendSample &a, qint64 t) { return a.timeUs < t; });
            QVERIFY(it != in.cend() && *it == s); // noisy() times are unique
        }
        QCOMPARE(outLo, lo);
        QCOMPARE(outHi, hi);
    }

    void preservesIsolatedPeaks()
    {
        // A flat 1 kHz signal with a one-sample spike and a one-sample dip: both survive a
        // 600x reduction, at their exact times.
        DecimatorSamples in;
        for (int i = 0; i < 600000; ++i)
            in.append({qint64(i) * 1000, 10.0});
        in[123457].value = 5000.0;
        in[400001].value = -3000.0;
        const SampleBuffer b = bufferOf(in);
        const DecimatorSamples out = Decimator::minMax(b, 0, in.last().timeUs, 1000);
        QCOMPARE(Decimator::minMax(b, 0, in.last().timeUs, 1000, Decimator::Strategy::Scan), out);
        QVERIFY(out.size() <= 2000);
        QVERIFY(out.contains(TrendSample{123457000, 5000.0}));
        QVERIFY(out.contains(TrendSample{400001000, -3000.0}));
        // Flat buckets give one point each, spiky buckets two.
        QCOMPARE(out.size(), 1000 + 2);
    }

    void summariesGiveTheSameResultAsAScan_data()
    {
        QTest::addColumn<int>("capacity");
        QTest::addColumn<int>("samples");
        QTest::addColumn<int>("levels"); // few levels: many ties; 0: sparse +1/-1 spikes on 0
        QTest::newRow("no wrap") << 100000 << 50000 << 1000000;
        QTest::newRow("wrapped, odd capacity") << 10007 << 50000 << 1000000;
        QTest::newRow("ties") << 9000 << 30000 << 3;
        QTest::newRow("sparse tied spikes") << 20000 << 30000 << 0;
        QTest::newRow("tiny capacity") << 5 << 1000 << 4;
    }
    void summariesGiveTheSameResultAsAScan()
    {
        QFETCH(int, capacity);
        QFETCH(int, samples);
        QFETCH(int, levels);
        QRandomGenerator rng(capacity ^ samples);
        DecimatorSamples all;
        qint64 t = 0;
        for (int i = 0; i < samples; ++i) {
            t += rng.bounded(4); // repeated times too
            // Sparse spikes: ties between whole blocks decide which sample is kept.
            const int r = int(rng.bounded(40));
            double v = levels > 0 ? double(rng.bounded(levels)) : (r == 0 ? 1.0 : r == 1 ? -1.0 : 0.0);
            if (rng.bounded(50) == 0)
                v = std::numeric_limits<double>::quiet_NaN();
            all.append({t, v});
        }
        SampleBuffer ring(capacity);
        for (const auto &s : all)
            QVERIFY(ring.append(s.timeUs, s.value));
        const DecimatorSamples kept = all.mid(all.size() - ring.size());
        QCOMPARE(ring.size(), std::min(capacity, samples));
        for (int round = 0; round < 40; ++round) {
            const qint64 a = kept.first().timeUs - 5
                + rng.bounded(qint64(kept.last().timeUs - kept.first().timeUs + 10));
            const qint64 b = a + rng.bounded(qint64(kept.last().timeUs - kept.first().timeUs + 10));
            const int buckets = 1 + rng.bounded(3000);
            const DecimatorSamples fast = Decimator::minMax(ring, a, b, buckets, Decimator::Strategy::Summaries);
            const DecimatorSamples scan = Decimator::minMax(kept, a, b, buckets);
            QCOMPARE(Decimator::minMax(ring, a, b, buckets, Decimator::Strategy::Scan), scan);
            QCOMPARE(fast.size(), scan.size());
            for (qsizetype k = 0; k < fast.size(); ++k) {
                QCOMPARE(fast.at(k).timeUs, scan.at(k).timeUs);
                QCOMPARE(fast.at(k).value, scan.at(k).value); // never NaN in the output
            }
        }
        // After shrinking the bound the summaries are rebuilt.
        ring.setCapacity(std::max(1, capacity / 3));
        const DecimatorSamples kept2 = all.mid(all.size() - ring.size());
        QCOMPARE(Decimator::minMax(ring, kept2.first().timeUs, kept2.last().timeUs, 97, Decimator::Strategy::Summaries),
                 Decimator::minMax(kept2, kept2.first().timeUs, kept2.last().timeUs, 97));
    }

    void ringBufferAgreesWithList()
    {
        const DecimatorSamples all = noisy(20000, 7);
        SampleBuffer ring(5000); // wraps: keeps the newest 5000
        for (const auto &s : all)
            ring.append(s.timeUs, s.value);
        const DecimatorSamples kept = all.mid(all.size() - 5000);
        QCOMPARE(ring.samples(), kept);
        const qint64 from = kept.at(100).timeUs;
        const qint64 to = kept.at(4900).timeUs;
        QCOMPARE(Decimator::minMax(ring, from, to, 321), Decimator::minMax(kept, from, to, 321));
    }
};

QTEST_APPLESS_MAIN(TestDecimator)
#include "tst_decimator.moc"
