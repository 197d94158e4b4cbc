// drivedesk-cli ping: the link health of one drive against the built-in simulator, for each
// family (servo-can on a private virtualcan hub); exit 1 when the drive does not answer.
#include <QtTest>

#include "tests/support/clirun.h"

#include <QJsonObject>

using namespace dd::test;

class TestCliPing : public QObject
{
    Q_OBJECT
private slots:
    void answeringDrive_data()
    {
        QTest::addColumn<QString>("family");
        QTest::newRow("servo-modbus") << QStringLiteral("servo-modbus");
        QTest::newRow("shuoke") << QStringLiteral("shuoke");
        QTest::newRow("servo-can (pipelined reads)") << QStringLiteral("servo-can");
    }
    void answeringDrive()
    {
        QFETCH(QString, family);
        const CliRun r = runCli({"--sim", "--family", family, "--json", "ping", "--count", "5"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        const QJsonObject j = r.json();
        QCOMPARE(j.value("command").toString(), QStringLiteral("ping"));
        QCOMPARE(j.value("count").toInt(), 5);
        QCOMPARE(j.value("answered").toInt(), 5);
        QVERIFY(j.value("requests").toInt() >= 5);
        QCOMPARE(j.value("timeouts").toInt(), 0);
        QCOMPARE(j.value("checksumErrors").toInt(), 0);
        const QJsonObject t = j.value("turnaroundMs").toObject();
        QVERIFY(t.value("min").toDouble() > 0);
        QVERIFY(t.value("min").toDouble() <= t.value("median").toDouble());
        QVERIFY(t.value("median").toDouble() <= t.value("max").toDouble());
        QVERIFY(j.value("recommendedTimeoutMs").toInt() >= 10);
        QCOMPARE(j.value("recommendedGapMs").toInt(), 0);
    }

    void textReport()
    {
        const CliRun r = runCli({"--sim", "--family", "servo-modbus", "ping", "--count", "3"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
        QVERIFY2(r.out.contains("Turnaround") && r.out.contains("Recommended timeout"), r.out.constData());
    }

    void silentDriveExitsOne()
    {
        // The simulated drive is at address 1; nobody answers at 9.
        const CliRun r = runCli({"--sim", "--family", "servo-modbus", "--sim-drives", "1", "--address", "9",
                                 "--timeout", "10", "--retries", "0", "--json", "ping", "--count", "2"});
        QCOMPARE(r.exitCode, 1);
        const QJsonObject j = r.json();
        QCOMPARE(j.value("ok").toBool(), false);
        QVERIFY2(r.text().contains("answered none of 2"), qPrintable(r.text()));
    }

    void badCountIsUsage()
    {
        const CliRun r = runCli({"--sim", "--family", "servo-modbus", "ping", "--count", "0"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.text().contains("--count"), qPrintable(r.text()));
    }
};

QTEST_GUILESS_MAIN(TestCliPing)
#include "tst_cliping.moc"
