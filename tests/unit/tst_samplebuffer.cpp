#include <QtTest>

#include <limits>

#include "core/trend/samplebuffer.h"
#include "tests/support/trendsamplestring.h"

using namespace dd;

class TestSampleBuffer : public QObject
{
    Q_OBJECT
private slots:
    // The cursor reads the line, not the nearest or the next sample; a gap reads as none.
    void lineValueFollowsTheLineAndGaps()
    {
        SampleBuffer b;
        QVERIFY(!b.lineValueAt(0));
        b.append(0, 0.0);
        b.append(1000, 10.0);
        b.append(2000, std::numeric_limits<double>::quiet_NaN());
        b.append(5000, 40.0);
        b.append(6000, 20.0);
        QCOMPARE(*b.lineValueAt(0), 0.0);
        QCOMPARE(*b.lineValueAt(900), 9.0); // nearest would say 10, "next" too
        QCOMPARE(*b.lineValueAt(1000), 10.0);
        QVERIFY(!b.lineValueAt(1500)); // between a sample and a gap marker
        QVERIFY(!b.lineValueAt(2000));
        QVERIFY(!b.lineValueAt(4000));
        QCOMPARE(*b.lineValueAt(5500), 30.0);
        QCOMPARE(*b.lineValueAt(6000), 20.0);
        QVERIFY(!b.lineValueAt(6001));
        QVERIFY(!b.lineValueAt(-1));
    }

    void gapTimesAreIndexedAndEvicted()
    {
        SampleBuffer b(4);
        const double nan = std::numeric_limits<double>::quiet_NaN();
        b.append(0, nan);
        b.append(10, 1);
        b.append(20, nan);
        b.append(30, 1);
        QCOMPARE(b.gapTimes(0, 30), (std::vector<qint64>{0, 20}));
        QCOMPARE(b.gapTimes(5, 30), (std::vector<qint64>{20}));
        b.append(40, 1); // evicts the gap at 0
        QCOMPARE(b.gapCount(), 1);
        QCOMPARE(b.gapTimes(0, 100), (std::vector<qint64>{20}));
        b.setCapacity(2); // keeps 30, 40
        QCOMPARE(b.gapCount(), 0);
        b.append(50, nan);
        QCOMPARE(b.gapTimes(0, 100), (std::vector<qint64>{50}));
        b.clear();
        QCOMPARE(b.gapCount(), 0);
    }

    void appendAndIndex()
    {
        SampleBuffer b(10);
        QVERIFY(b.isEmpty());
        QVERIFY(b.append(100, 1.0));
        QVERIFY(b.append(200, 2.0));
        QVERIFY(b.append(200, 2.5)); // equal times are fine
        QCOMPARE(b.size(), 3);
        QCOMPARE(b.at(0), (TrendSample{100, 1.0}));
        QCOMPARE(b.at(2), (TrendSample{200, 2.5}));
        QCOMPARE(b.firstTimeUs(), 100);
        QCOMPARE(b.lastTimeUs(), 200);
        QCOMPARE(b.droppedCount(), 0u);
    }

    void rejectsOlderSamples()
    {
        SampleBuffer b(10);
        QVERIFY(b.append(100, 1.0));
        QVERIFY(!b.append(99, 5.0));
        QCOMPARE(b.size(), 1);
        QCOMPARE(b.rejectedCount(), 1u);
        QCOMPARE(b.lastTimeUs(), 100);
    }

    void ringKeepsNewest()
    {
        SampleBuffer b(4);
        for (int i = 0; i < 10; ++i)
            QVERIFY(b.append(i * 10, i));
        QCOMPARE(b.size(), 4);
        QCOMPARE(b.droppedCount(), 6u);
        const QList<TrendSample> expected{{60, 6}, {70, 7}, {80, 8}, {90, 9}};
        QCOMPARE(b.samples(), expected);
        QCOMPARE(b.firstTimeUs(), 60);
        // Lookups across the wrap point.
        QCOMPARE(b.lowerBound(75), 2);
        QCOMPARE(b.upperBound(80), 3);
        QCOMPARE(b.samples(65, 85), (QList<TrendSample>{{70, 7}, {80, 8}}));
        // Still rejects older samples after wrapping.
        QVERIFY(!b.append(89, 0));
        QVERIFY(b.append(90, 9.5));
        QCOMPARE(b.at(3), (TrendSample{90, 9.5}));
        QCOMPARE(b.at(0), (TrendSample{70, 7}));
    }

    void boundsAndWindow()
    {
        SampleBuffer b(100);
        for (qint64 t : {10, 20, 20, 30, 50})
            b.append(t, double(t));
        QCOMPARE(b.lowerBound(0), 0);
        QCOMPARE(b.lowerBound(20), 1);
        QCOMPARE(b.upperBound(20), 3);
        QCOMPARE(b.lowerBound(40), 4);
        QCOMPARE(b.upperBound(50), 5);
        QCOMPARE(b.lowerBound(51), 5);
        QCOMPARE(b.samples(20, 30).size(), 3);
        QCOMPARE(b.samples(31, 49).size(), 0);
        QCOMPARE(b.samples(30, 20).size(), 0);
        QCOMPARE(b.samples(-1000, 1000).size(), 5);
    }

    void nearest()
    {
        SampleBuffer b(100);
        QVERIFY(!b.nearest(0).has_value());
        b.append(10, 1);
        b.append(20, 2);
        b.append(40, 4);
        QCOMPARE(*b.nearest(-5), (TrendSample{10, 1}));
        QCOMPARE(*b.nearest(14), (TrendSample{10, 1}));
        QCOMPARE(*b.nearest(15), (TrendSample{10, 1})); // tie: the earlier
        QCOMPARE(*b.nearest(16), (TrendSample{20, 2}));
        QCOMPARE(*b.nearest(31), (TrendSample{40, 4}));
        QCOMPARE(*b.nearest(1000), (TrendSample{40, 4}));
    }

    void lookupsOnLargeWrappedBuffer()
    {
        // 1M samples wrapped twice; every lookup must match a linear reference.
        SampleBuffer b(1 << 20);
        const qint64 n = 3 * (1 << 20) / 2;
        for (qint64 i = 0; i < n; ++i)
            b.append(i * 3, double(i));
        QCOMPARE(b.size(), 1 << 20);
        const qint64 first = (n - (1 << 20)) * 3;
        QCOMPARE(b.firstTimeUs(), first);
        for (qint64 t : {first - 1, first, first + 1, first + 3000, (n - 1) * 3, n * 3}) {
            const qsizetype lb = b.lowerBound(t);
            const qsizetype expected = t <= first ? 0 : std::min<qint64>((t - first + 2) / 3, b.size());
            QCOMPARE(lb, expected);
        }
    }

    void memoryGrowsWithRecordingAndStaysBounded()
    {
        SampleBuffer b(5000);
        QCOMPARE(b.memoryBytes(), 0);
        b.append(0, 0);
        QVERIFY(b.memoryBytes() > 0);
        QVERIFY(b.memoryBytes() <= 1024 * 16 + 16 * 32);
        for (int i = 1; i < 20000; ++i)
            b.append(i, i);
        // Exactly the bound plus the block summaries (32 bytes per 64 samples), never more.
        QCOMPARE(b.memoryBytes(), 5000 * 16 + (5000 / 64 + 2) * 32);
        QCOMPARE(b.size(), 5000);
        b.clear();
        QCOMPARE(b.memoryBytes(), 0);
        QCOMPARE(b.size(), 0);
        QCOMPARE(b.droppedCount(), 0u);
    }

    void extremes()
    {
        SampleBuffer b(1000);
        // 200 samples: values rise to 150 at index 150 and fall; 7 at 10 and 20 (ties).
        for (int i = 0; i < 200; ++i)
            b.append(i, i <= 150 ? i : 300 - i);
        b.append(200, 149); // equal to the value at 151, later: not the max of [151, 201)
        QCOMPARE(b.extremes(0, b.size()).minIndex, 0);
        QCOMPARE(b.extremes(0, b.size()).maxIndex, 150);
        QCOMPARE(b.extremes(151, b.size()).maxIndex, 151); // 149 at 151; 150 at 200 is later
        QCOMPARE(b.extremes(151, b.size()).minIndex, 199);
        QCOMPARE(b.extremes(5, 6).minIndex, 5);
        QCOMPARE(b.extremes(5, 6).maxIndex, 5);
        QCOMPARE(b.extremes(6, 6).minIndex, -1);
        QCOMPARE(b.extremes(-10, 100000).maxIndex, 150);
        SampleBuffer n(10);
        n.append(0, std::numeric_limits<double>::quiet_NaN());
        QCOMPARE(n.extremes(0, 1).minIndex, -1);
    }

    void defaultBoundIsTenMinutesAtOneKilohertz()
    {
        QCOMPARE(SampleBuffer::DefaultCapacity, qsizetype(1000 * 600));
        SampleBuffer b;
        QCOMPARE(b.capacity(), SampleBuffer::DefaultCapacity);
    }

    void setCapacityKeepsNewest()
    {
        SampleBuffer b(8);
        for (int i = 0; i < 12; ++i)
            b.append(i, i);
        b.setCapacity(3);
        QCOMPARE(b.samples(), (QList<TrendSample>{{9, 9}, {10, 10}, {11, 11}}));
        QCOMPARE(b.droppedCount(), 4u + 5u);
        b.setCapacity(5);
        b.append(12, 12);
        b.append(13, 13);
        b.append(14, 14);
        QCOMPARE(b.samples(), (QList<TrendSample>{{10, 10}, {11, 11}, {12, 12}, {13, 13}, {14, 14}}));
        b.setCapacity(0);
        QCOMPARE(b.capacity(), 1);
        QCOMPARE(b.samples(), (QList<TrendSample>{{14, 14}}));
    }
};

QTEST_APPLESS_MAIN(TestSampleBuffer)
#include "tst_samplebuffer.moc"
