// pinLocalTimeZone() (core/common/localtimezone.h): TZ set to the zone glibc uses anyway
// when it was unset, left alone when set.
#include <QtTest>

#include "core/common/localtimezone.h"

#include <QDateTime>

class TestLocalTimeZone : public QObject
{
    Q_OBJECT

private slots:
    void pinsTheSameZoneWhenUnset();
    void leavesASetZoneAlone();
};

void TestLocalTimeZone::pinsTheSameZoneWhenUnset()
{
#ifndef Q_OS_LINUX
    QSKIP("Linux (glibc) only");
#else
    if (!QFile::exists(QStringLiteral("/etc/localtime")))
        QSKIP("no /etc/localtime on this machine");
    qunsetenv("TZ");
    const QDateTime probe(QDate(2026, 7, 1), QTime(12, 0));
    const int offsetBefore = probe.offsetFromUtc();
    QVERIFY(dd::pinLocalTimeZone());
    QCOMPARE(qgetenv("TZ"), QByteArray(":/etc/localtime"));
    QCOMPARE(QDateTime(QDate(2026, 7, 1), QTime(12, 0)).offsetFromUtc(), offsetBefore);
    QVERIFY(!dd::pinLocalTimeZone()); // set now: left alone
#endif
}

void TestLocalTimeZone::leavesASetZoneAlone()
{
    qputenv("TZ", "UTC");
    QVERIFY(!dd::pinLocalTimeZone());
    QCOMPARE(qgetenv("TZ"), QByteArray("UTC"));
}

QTEST_GUILESS_MAIN(TestLocalTimeZone)
#include "tst_localtimezone.moc"
