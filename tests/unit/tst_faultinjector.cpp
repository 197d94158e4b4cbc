#include <QtTest>

#include "sim/bus/faultinjector.h"

using namespace dd;

class TestFaultInjector : public QObject
{
    Q_OBJECT
private slots:
    void defaultsInjectNothing()
    {
        FaultInjector f;
        const QByteArray frame = QByteArray::fromHex("0103000000 0ac5cd");
        for (int i = 0; i < 1000; ++i) {
            QVERIFY(!f.dropNow());
            QCOMPARE(f.corrupt(frame), frame);
            QVERIFY(!f.lastCorrupted());
            QCOMPARE(f.extraLatencyMs(), 0);
        }
        QVERIFY(!f.isSilent());
    }

    void deterministicPerSeed()
    {
        FaultSettings s;
        s.dropRate = 0.3;
        s.corruptRate = 0.4;
        s.extraLatencyMs = 5;
        s.latencyJitterMs = 10;
        s.seed = 1234;
        const auto run = [](FaultInjector &f) {
            QByteArray trace;
            const QByteArray frame = QByteArray::fromHex("0110006400020400010002");
            for (int i = 0; i < 500; ++i) {
                trace += f.dropNow() ? 'D' : '.';
                trace += f.corrupt(frame).toHex();
                trace += QByteArray::number(f.extraLatencyMs());
            }
            return trace;
        };
        FaultInjector a(s), b(s);
        const QByteArray ta = run(a);
        QCOMPARE(run(b), ta);
        a.setSettings(s); // restarts the sequence
        QCOMPARE(run(a), ta);
        s.seed = 1235;
        FaultInjector c(s);
        QVERIFY(run(c) != ta);
    }

    void ratesWithinTolerance_data()
    {
        QTest::addColumn<double>("rate");
        QTest::newRow("1%") << 0.01;
        QTest::newRow("10%") << 0.10;
        QTest::newRow("50%") << 0.50;
        QTest::newRow("90%") << 0.90;
    }
    void ratesWithinTolerance()
    {
        QFETCH(double, rate);
        FaultSettings s;
        s.dropRate = rate;
        s.corruptRate = rate;
        s.seed = 7;
        FaultInjector f(s);
        const int n = 10000;
        int drops = 0, corrupted = 0;
        const QByteArray frame = QByteArray::fromHex("0103020001b844");
        for (int i = 0; i < n; ++i) {
            drops += f.dropNow() ? 1 : 0;
            const QByteArray out = f.corrupt(frame);
            if (out != frame) {
                ++corrupted;
                // exactly one bit differs
                int bits = 0;
                for (int k = 0; k < frame.size(); ++k)
                    bits += qPopulationCount(static_cast<quint8>(out[k] ^ frame[k]));
                QCOMPARE(bits, 1);
                QVERIFY(f.lastCorrupted());
            }
        }
        // 4 standard deviations of a binomial(n, rate)
        const double tol = 4.0 * std::sqrt(n * rate * (1 - rate));
        QVERIFY2(std::abs(drops - n * rate) <= tol, qPrintable(QString::number(drops)));
        QVERIFY2(std::abs(corrupted - n * rate) <= tol, qPrintable(QString::number(corrupted)));
    }

    void corruptionHitsEveryBytePosition()
    {
        FaultSettings s;
        s.corruptRate = 1.0;
        FaultInjector f(s);
        const QByteArray frame(6, '\0');
        QSet<int> positions, bits;
        for (int i = 0; i < 2000; ++i) {
            const QByteArray out = f.corrupt(frame);
            for (int k = 0; k < out.size(); ++k) {
                if (out[k]) {
                    positions.insert(k);
                    bits.insert(qCountTrailingZeroBits(static_cast<quint8>(out[k])));
                }
            }
        }
        QCOMPARE(positions.size(), 6);
        QCOMPARE(bits.size(), 8);
        QCOMPARE(f.corrupt(QByteArray()), QByteArray());
    }

    void latencyJitterRange()
    {
        FaultInjector f;
        f.setExtraLatency(20, 5);
        QSet<int> seen;
        for (int i = 0; i < 10000; ++i) {
            const int ms = f.extraLatencyMs();
            QVERIFY(ms >= 20 && ms <= 25);
            seen.insert(ms);
        }
        QCOMPARE(seen.size(), 6);
    }

    void parseSettings()
    {
        QString error;
        const auto s = FaultSettings::parse(QStringLiteral("drop=0.1, corrupt=5%,latency=20,jitter=3,silent,seed=99"),
                                            &error);
        QVERIFY2(s, qPrintable(error));
        QCOMPARE(s->dropRate, 0.1);
        QCOMPARE(s->corruptRate, 0.05);
        QCOMPARE(s->extraLatencyMs, 20);
        QCOMPARE(s->latencyJitterMs, 3);
        QVERIFY(s->silent);
        QCOMPARE(s->seed, 99u);
        QCOMPARE(FaultSettings::parse(s->toString()), s);
        QCOMPARE(FaultSettings::parse(QString()), FaultSettings{});
        QVERIFY(!FaultSettings::parse(QStringLiteral("drop=2"), &error));
        QVERIFY(error.contains(QLatin1String("drop")));
        QVERIFY(!FaultSettings::parse(QStringLiteral("latency=-1"), &error));
        QVERIFY(!FaultSettings::parse(QStringLiteral("bogus=1"), &error));
        QVERIFY(error.contains(QLatin1String("bogus")));
        QVERIFY(!FaultSettings::parse(QStringLiteral("drop"), &error));
        QVERIFY(!FaultSettings::parse(QStringLiteral("silent=maybe"), &error));
        QCOMPARE(FaultSettings::parse(QStringLiteral("silent=0"))->silent, false);
    }
};

QTEST_APPLESS_MAIN(TestFaultInjector)
#include "tst_faultinjector.moc"
