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
    void servoCanMotionNeedsEnable_data();
    void servoCanMotionNeedsEnable();
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
    const CliRun r = runCli(
        {"--sim", "--family", "servo-can", "--json", "--trace", "jog", "100", "--duration", "0.3", "--enable"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(r.json().value("stoppedBy").toString(), QStringLiteral("duration"));
    QVERIFY(r.err.contains("065#01 20 00 64 00 00 00 FF")); // "speed mode +100" (the seed's example, station 1)
    QVERIFY(r.err.contains("(stop)"));
    QVERIFY(r.json().value("powerStageOn").toBool()); // said, since --enable allowed it
    QVERIFY(r.err.contains("enable off"));
}

// Issue #26: servo-can's 0x20..0x22 switch the power stage on by themselves and nothing reads
// back whether it is on, so jog, move and step run only with --enable: without it they are
// refused before any motion frame (only the identification reads go out).
void TestCliSim::servoCanMotionNeedsEnable_data()
{
    QTest::addColumn<QStringList>("command");
    QTest::newRow("jog") << QStringList{"jog", "100", "--duration", "0.3"};
    QTest::newRow("move") << QStringList{"move", "--by", "1000", "--speed", "300"};
    QTest::newRow("step") << QStringList{"step",        "velocity", "300",          "--duration", "0.2",
                                         "--max-speed", "500",      "--max-travel", "100000"};
}

void TestCliSim::servoCanMotionNeedsEnable()
{
    QFETCH(QStringList, command);
    const CliRun r = runCli(QStringList{"--sim", "--family", "servo-can", "--json", "--trace"} + command);
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.json().value("error").toObject().value("code").toString(), QStringLiteral("invalid-argument"));
    QVERIFY2(r.json().value("error").toObject().value("message").toString().contains("--enable"), r.out.constData());
    // No speed-mode, relative, absolute or positioning-speed frame (command bytes 0x20..0x23).
    static const QRegularExpression motion(QStringLiteral("#[0-9A-F]{2} 2[0-3] "));
    QVERIFY2(!QString::fromUtf8(r.err).contains(motion), r.err.constData());
    QVERIFY(r.err.contains("#01 12 ")); // the identification did go out: the trace is there
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
