#include <QtTest>

#include "core/trend/trendaxisscale.h"

#include <limits>

using namespace dd;

class TestTrendAxisScale : public QObject
{
    Q_OBJECT
private slots:
    void niceStep_data()
    {
        QTest::addColumn<double>("rough");
        QTest::addColumn<double>("step");
        QTest::newRow("10 s / 6") << 10.0 / 6 << 2.0;
        QTest::newRow("30 s / 6") << 5.0 << 5.0;
        QTest::newRow("1 min / 6") << 10.0 << 10.0;
        QTest::newRow("2 min / 6") << 20.0 << 20.0;
        QTest::newRow("10 min / 6") << 100.0 << 100.0;
        QTest::newRow("1.4") << 1.4 << 1.0;
        QTest::newRow("3.4") << 3.4 << 2.0;
        QTest::newRow("7.6") << 7.6 << 10.0;
        QTest::newRow("small") << 0.0031 << 0.002;
        QTest::newRow("zero") << 0.0 << 1.0;
        QTest::newRow("negative") << -3.0 << 1.0;
        QTest::newRow("nan") << std::numeric_limits<double>::quiet_NaN() << 1.0;
        QTest::newRow("inf") << std::numeric_limits<double>::infinity() << 1.0;
    }
    void niceStep()
    {
        QFETCH(double, rough);
        QFETCH(double, step);
        QCOMPARE(TrendAxisScale::niceStep(rough), step);
    }

    void fitValueRange()
    {
        using R = std::pair<double, double>;
        // Data 0..100 on a far-off axis: 5 % margins.
        QCOMPARE(TrendAxisScale::fitValueRange(0, 100, 1000, 2000), R(-5, 105));
        // Fits and fills more than half: kept.
        QCOMPARE(TrendAxisScale::fitValueRange(0, 100, -10, 120), R(-10, 120));
        // Fits but fills less than half: shrinks.
        QCOMPARE(TrendAxisScale::fitValueRange(0, 100, -200, 200), R(-5, 105));
        // Outside on one side: grows.
        QCOMPARE(TrendAxisScale::fitValueRange(0, 130, -10, 120), R(-6.5, 136.5));
        // A flat line: ±10 % of the value, at least ±1.
        QCOMPARE(TrendAxisScale::fitValueRange(311.5, 311.5, 0, 1), R(311.5 - 31.15, 311.5 + 31.15));
        QCOMPARE(TrendAxisScale::fitValueRange(0, 0, 50, 60), R(-1, 1));
    }
};

QTEST_APPLESS_MAIN(TestTrendAxisScale)
#include "tst_trendaxisscale.moc"
