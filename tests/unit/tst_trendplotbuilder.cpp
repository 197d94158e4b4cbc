#include <QtTest>

#include "core/trend/samplebuffer.h"
#include "core/trend/trendplotbuilder.h"

#include <algorithm>
#include <cmath>
#include <limits>

using namespace dd;

class TestTrendPlotBuilder : public QObject
{
    Q_OBJECT
private slots:
    // A gap marker between two samples breaks the line (a NaN point between them): the
    // plot must not draw a ramp across a time the drive was not heard.
    void gapsBreakTheLine()
    {
        SampleBuffer b;
        b.append(0, 0.0);
        b.append(1000000, 0.0);
        b.append(2000000, std::numeric_limits<double>::quiet_NaN()); // link lost
        b.append(9000000, 8.0);
        b.append(10000000, 8.0);
        const auto r = TrendPlotBuilder::build(b, 0, 10000000, 200, 0);
        QCOMPARE(r.points.size(), 5);
        QCOMPARE(r.points.at(1), QPointF(1.0, 0.0));
        QCOMPARE(r.points.at(2).x(), 9.0);
        QVERIFY(std::isnan(r.points.at(2).y()));
        QCOMPARE(r.points.at(3), QPointF(9.0, 8.0));
        QCOMPARE(r.yMin, 0.0);
        QCOMPARE(r.yMax, 8.0);
        // Decimated (1 bucket per 5 s) the break stays.
        const auto coarse = TrendPlotBuilder::build(b, 0, 10000000, 3, 0);
        QVERIFY(std::any_of(coarse.points.cbegin(), coarse.points.cend(),
                            [](const QPointF &p) { return std::isnan(p.y()); }));
        // A window after the gap has no break.
        const auto later = TrendPlotBuilder::build(b, 9000000, 10000000, 200, 0);
        for (const QPointF &p : later.points)
            QVERIFY(!std::isnan(p.y()));
    }

    void mapsAndAddsEdgePoints()
    {
        SampleBuffer b;
        // origin 1 s; samples every 0.5 s
        for (int i = 0; i < 8; ++i)
            b.append(1000000 + i * 500000, i);
        // Window [2 s, 3 s] after the origin -> samples 4, 5, 6 inside; 3 and 7 are edges.
        const auto r = TrendPlotBuilder::build(b, 3000000, 4000000, 100, 1000000, 2.0, -1.0);
        const QList<QPointF> expected{{1.5, 5}, {2.0, 7}, {2.5, 9}, {3.0, 11}, {3.5, 13}};
        QCOMPARE(r.points, expected);
        QVERIFY(r.hasData());
        QCOMPARE(r.yMin, 7.0); // edges excluded
        QCOMPARE(r.yMax, 11.0);
    }

    void noEdgesAtTheEndsOfTheRecording()
    {
        SampleBuffer b;
        b.append(0, 1);
        b.append(10, 2);
        const auto r = TrendPlotBuilder::build(b, 0, 10, 100, 0);
        QCOMPARE(r.points, (QList<QPointF>{{0, 1}, {0.00001, 2}}));
    }

    void emptyWindowStillDrawsTheCrossingLine()
    {
        SampleBuffer b;
        b.append(0, 1);
        b.append(1000000, 3);
        const auto r = TrendPlotBuilder::build(b, 200000, 800000, 100, 0);
        QCOMPARE(r.points, (QList<QPointF>{{0, 1}, {1, 3}}));
        QVERIFY(!r.hasData());
        QVERIFY(!TrendPlotBuilder::build(SampleBuffer(), 0, 10, 100, 0).hasData());
        QVERIFY(TrendPlotBuilder::build(b, 10, 0, 100, 0).points.isEmpty());
    }

    void nanEdgesAreSkipped()
    {
        SampleBuffer b;
        b.append(0, std::numeric_limits<double>::quiet_NaN());
        b.append(5, 1);
        b.append(9, std::numeric_limits<double>::quiet_NaN());
        QCOMPARE(TrendPlotBuilder::build(b, 2, 7, 10, 0).points, (QList<QPointF>{{0.000005, 1}}));
    }

    void atMostTwoPointsPerPixel()
    {
        SampleBuffer b;
        for (int i = 0; i < 200000; ++i)
            b.append(i * 100, (i * 7919) % 1000);
        for (int width : {1, 2, 3, 50, 640, 1999}) {
            const auto r = TrendPlotBuilder::build(b, 1000000, 15000000, width, 0);
            QVERIFY2(r.points.size() <= 2 * width, qPrintable(QString::number(width)));
            QCOMPARE(r.yMin, 0.0);
            QCOMPARE(r.yMax, 999.0);
        }
    }
};

QTEST_APPLESS_MAIN(TestTrendPlotBuilder)
#include "tst_trendplotbuilder.moc"
