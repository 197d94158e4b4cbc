// drivedesk-cli --sim: the built-in simulated bench, nothing plugged in.
#include "tests/support/clirun.h"

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
    void monitorTextColumnsLineUp();
    void monitorDefaultsToTheLinksRate();
    void backupOfASimulatedDrive();
    void simLeavesNoRoomForAPort();
    void stateCarriesOverBetweenRuns();
};

void TestCliSim::info_data()
{
    QTest::addColumn<QString>("family");
    QTest::newRow("servo-modbus") << QStringLiteral("servo-modbus");
    QTest::newRow("servo-can") << QStringLiteral("servo-can");
    QTest::newRow("shuoke") << QStringLiteral("shuoke");
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
    // The simulator shares the CLI's thread: allow the probes more than the adaptive minimum.
    const CliRun r = runCli({"--sim", "--sim-drives", "5@19200,9@38400", "--timeout", "100", "--json", "scan", "--to",
                             "12", "--bauds", "19200,38400"});
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
    QVERIFY(r.err.contains("065#01 20 00 64 00 00 00 FF")); // "speed mode +100" (the seed's example, station 1)
    QVERIFY(r.err.contains("(stop)"));
}

void TestCliSim::monitorTextColumnsLineUp()
{
    // Headers wider than the usual 14 columns ("position-error [pulses]"): every value ends
    // where its header ends.
    const CliRun r = runCli({"--sim", "--family", "servo-can", "monitor", "speed,position-error,bus-voltage",
                             "--duration", "0.35", "--rate", "10"});
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    const QStringList lines = QString::fromUtf8(r.out).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    QVERIFY(lines.size() >= 3);
    auto columnEnds = [](const QString &line) {
        QList<int> ends;
        for (int i = 0; i < line.size(); ++i)
            if (line.at(i) != QLatin1Char(' ') && (i + 1 == line.size() || line.at(i + 1) == QLatin1Char(' ')))
                ends << i;
        return ends;
    };
    // The header's cells contain spaces ("time [s]"): take the end of each "]".
    QList<int> headerEnds;
    for (int i = 0; i < lines.first().size(); ++i)
        if (lines.first().at(i) == QLatin1Char(']'))
            headerEnds << i;
    QCOMPARE(headerEnds.size(), 4);
    for (int k = 1; k < lines.size(); ++k)
        QCOMPARE(columnEnds(lines.at(k)), headerEnds);
}

void TestCliSim::monitorDefaultsToTheLinksRate()
{
    // Without --rate: as fast as the link carries the channels (the GUI trend's default),
    // not a fixed 10 Hz; the summary says which rate was used.
    CliRun r = runCli({"--sim", "--family", "servo-can", "--json", "monitor", "speed", "--duration", "0.3"});
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    const QJsonObject summary = r.jsonLines().last();
    QVERIFY2(summary.value("rateHz").toDouble() > 10.0, qPrintable(r.text()));
    QVERIFY(summary.value("rateHz").toDouble() <= 1000.0);
    r = runCli({"--sim", "--family", "servo-can", "--json", "monitor", "speed", "--duration", "0.3", "--rate", "7"});
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(r.jsonLines().last().value("rateHz").toDouble(), 7.0);
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

void TestCliSim::stateCarriesOverBetweenRuns()
{
    QTemporaryDir dir;
    const QString state = dir.filePath(QStringLiteral("bench.json"));
    CliRun r = runCli({"--sim-state", state, "set", "PA12=321"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY(QFile::exists(state));
    r = runCli({"--sim-state", state, "--json", "get", "PA12"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(r.json().value("parameters").toArray().at(0).toObject().value("value").toInt(), 321);
    // Without the state file a fresh drive has its factory value again.
    r = runCli({"--sim", "--json", "get", "PA12"});
    QVERIFY(r.json().value("parameters").toArray().at(0).toObject().value("value").toInt() != 321);
}

QTEST_GUILESS_MAIN(TestCliSim)
#include "tst_clisim.moc"
