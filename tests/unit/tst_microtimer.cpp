#include <QtTest>

#include <QElapsedTimer>
#include <QSignalSpy>

#include "core/common/microtimer.h"

using namespace dd;

// MicroTimer: single shot, never early, stop and restart, microsecond waits where precise.
class tst_MicroTimer : public QObject
{
    Q_OBJECT

private slots:
    void firesOnceNotEarly_data()
    {
        QTest::addColumn<qint64>("waitUs");
        QTest::addColumn<qint64>("earlyWakeUs");
        QTest::newRow("300 us") << qint64(300) << qint64(0);
        QTest::newRow("2.7 ms") << qint64(2700) << qint64(0);
        QTest::newRow("zero") << qint64(0) << qint64(0);
        QTest::newRow("negative") << qint64(-50) << qint64(0);
        // Waking early must not fire early: the rest is waited out awake.
        QTest::newRow("300 us, early wake 150") << qint64(300) << qint64(150);
        QTest::newRow("100 us, early wake 150") << qint64(100) << qint64(150);
        QTest::newRow("2.7 ms, early wake 150") << qint64(2700) << qint64(150);
        QTest::newRow("zero, early wake 150") << qint64(0) << qint64(150);
    }

    void firesOnceNotEarly()
    {
        QFETCH(qint64, waitUs);
        MicroTimer t;
        QFETCH(qint64, earlyWakeUs);
        t.setEarlyWakeUs(earlyWakeUs);
        QSignalSpy spy(&t, &MicroTimer::timeout);
        QElapsedTimer clock;
        clock.start();
        t.start(waitUs);
        QVERIFY(t.isActive());
        QVERIFY(spy.wait(2000));
        const qint64 elapsedUs = clock.nsecsElapsed() / 1000;
        QVERIFY2(elapsedUs >= waitUs, qPrintable(QStringLiteral("fired after %1 us").arg(elapsedUs)));
        QVERIFY(!t.isActive());
        QVERIFY(!spy.wait(20)); // single shot
        QCOMPARE(spy.count(), 1);
    }

    void earlyWakeIsBoundedAndOffWhereImprecise()
    {
        MicroTimer t;
        t.setEarlyWakeUs(5000); // more than a millisecond of waiting awake is never wanted
        QCOMPARE(t.earlyWakeUs(), t.isPrecise() ? qint64(1000) : qint64(0));
        t.setEarlyWakeUs(-3);
        QCOMPARE(t.earlyWakeUs(), qint64(0));
    }

    void stopPreventsTimeout()
    {
        MicroTimer t;
        QSignalSpy spy(&t, &MicroTimer::timeout);
        t.start(1000);
        t.stop();
        QVERIFY(!t.isActive());
        QVERIFY(!spy.wait(30));
    }

    void restartReplacesPendingTime()
    {
        MicroTimer t;
        QSignalSpy spy(&t, &MicroTimer::timeout);
        QElapsedTimer clock;
        clock.start();
        t.start(500);
        t.start(20000);
        QVERIFY(spy.wait(2000));
        QVERIFY(clock.nsecsElapsed() / 1000 >= 20000);
        QVERIFY(!spy.wait(30));
        QCOMPARE(spy.count(), 1);
    }

    void subMillisecondWaitsWhenPrecise()
    {
        MicroTimer t;
#ifdef Q_OS_LINUX
        QVERIFY(t.isPrecise());
#endif
        if (!t.isPrecise())
            QSKIP("millisecond fallback on this platform");
        // 300 waits of 100 us: a millisecond timer needs at least 300 ms. Allow for the
        // wake-ups of a loaded machine, but not for rounding every wait up to a millisecond.
        QSignalSpy spy(&t, &MicroTimer::timeout);
        QElapsedTimer clock;
        clock.start();
        for (int i = 0; i < 300; ++i) {
            t.start(100);
            QVERIFY(spy.wait(1000));
        }
        const qint64 totalUs = clock.nsecsElapsed() / 1000;
        QVERIFY2(totalUs >= 300 * 100, qPrintable(QString::number(totalUs)));
        QVERIFY2(totalUs < 290 * 1000, qPrintable(QStringLiteral("300 waits took %1 us").arg(totalUs)));
        qDebug("300 waits of 100 us took %lld us", totalUs);
    }
};

QTEST_GUILESS_MAIN(tst_MicroTimer)
#include "tst_microtimer.moc"
