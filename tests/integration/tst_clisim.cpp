// drivedesk-cli --sim: the built-in simulated bench, nothing plugged in.
#include "clirun.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace dd::test;

class TestCliSim : public QObject
{
    Q_OBJECT

private slots:
    void info_data();
    void info();
    void scanFindsSimulatedDrives();
    void jogRunsAndStops();
    void backupOfASimulatedDrive();
    void simLeavesNoRoomForAPort();
};

void TestCliSim::info_data()
{
    QTest::addColumn<QString>("family");
    QTest::newRow("servo-modbus") << QStringLiteral("servo-modbus");
    QTest::newRow("servo-can") << QStringLiteral("servo-can");
}

void TestCliSim::info()
{
    QFETCH(QString, family);
    const CliRun r = runCli({"--sim", "--family", family, "--address", "4", "--json", "info"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(r.json().value("identity").toObject().value("family").toString(), family);
    QCOMPARE(r.json().value("identity").toObject().value("address").toInt(), 4);
    QVERIFY(r.err.contains("simulated"));
}

void TestCliSim::scanFindsSimulatedDrives()
{
    const CliRun r = runCli({"--sim", "--sim-drives", "5@19200,9@19200", "--baud", "19200", "--json", "scan"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QList<int> found;
    for (const QJsonValue &v : r.json().value("drives").toArray())
        found << v.toObject().value("address").toInt();
    std::sort(found.begin(), found.end());
    QCOMPARE(found, (QList<int>{5, 9}));
}

void TestCliSim::jogRunsAndStops()
{
    const CliRun r = runCli({"--sim", "--family", "servo-can", "--json", "--trace", "jog", "100", "--duration", "0.3"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(r.json().value("stoppedBy").toString(), QStringLiteral("duration"));
    QVERIFY(r.err.contains("00 20 00 64 00 00 00 FF"));   // the seed's "speed mode +100" frame
    QVERIFY(r.err.contains("(stop)"));
}

void TestCliSim::backupOfASimulatedDrive()
{
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("sim.json"));
    CliRun r = runCli(QStringList{"--sim", "backup", "-o", file});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    // A fresh simulated drive has the same factory values: nothing to restore.
    r = runCli(QStringList{"--sim", "--json", "restore", file});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY(r.json().value("selected").toArray().isEmpty());
}

void TestCliSim::simLeavesNoRoomForAPort()
{
    const CliRun r = runCli({"--sim", "--port", "/dev/ttyUSB0", "info"});
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains("--sim"));
}

QTEST_GUILESS_MAIN(TestCliSim)
#include "tst_clisim.moc"
