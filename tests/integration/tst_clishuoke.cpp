// drivedesk-cli against simulated Shuoke drives in every framing (RTU, ASCII, PLC on a pty;
// CAN on a private virtualcan hub), the benches living in this process: every command, the
// backup → change → diff → restore → verify cycle, write-only settings, input errors with
// nothing on the wire, jog ending by duration / SIGINT / SIGTERM, scan.
#include "tests/support/clirun.h"

#include "core/common/coreresources.h"
#include "core/params/backupfile.h"
#include "core/protocol/shuoke/shuokecommands.h"
#include "sim/bus/simserialbus.h"
#include "tests/support/shuokecanbench.h"
#include "tests/support/shuokeserialbench.h"

#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <memory>

using namespace dd;
using namespace dd::test;

class TestCliShuoke : public QObject
{
    Q_OBJECT

public:
    enum Bench { Rtu, Ascii, Plc, Can };

private slots:
    void initTestCase();
    void init();
    void infoInEveryFraming_data();
    void infoInEveryFraming();
    void getAndSetInEveryFraming_data();
    void getAndSetInEveryFraming();
    void writeOnlySettings();
    void setOutOfRangeSendsNothing();
    void backupChangeDiffRestoreVerify_data();
    void backupChangeDiffRestoreVerify();
    void jogStopsWhenItsDurationEnds();
    void jogStopsOnSignal_data();
    void jogStopsOnSignal();
    void moveAndHome();
    void aHomingStoppedElsewhereIsNotDone();
    void stopAndEmergencyStop();
    void monitor();
    void unsupportedOperationsExit2();
    void scanSerialFindsUnknownAddressesAndBauds();
    void scanCan();
    void familyOptions();

private:
    QStringList args(Bench bench, std::initializer_list<const char *> words) const;
    SimShuokeDrive &sim(Bench bench);
    static void addBenchRows();

    QTemporaryDir m_dir;
    ShuokeSerialBench m_rtu;   // drive 3
    ShuokeSerialBench m_scan;  // drive 3 at 9600, drive 12 at 19200: only for the scan
    ShuokeSerialBench m_ascii; // drive 4
    ShuokeSerialBench m_plc;   // drive 5
    ShuokeCanBench m_can;      // drives 6 and 9
    SimShuokeSerialDevice *m_rtu3 = nullptr;
    SimShuokeSerialDevice *m_ascii4 = nullptr;
    SimShuokeSerialDevice *m_plc5 = nullptr;
    SimShuokeCanDevice *m_can6 = nullptr;
};

Q_DECLARE_METATYPE(TestCliShuoke::Bench)

namespace {

SimShuokeDrive::Config driveConfig(int address, int baudCode = 6)
{
    SimShuokeDrive::Config c;
    c.address = quint8(address);
    c.baudCode = baudCode;
    c.powerUpWindowMs = 0; // at the configured rate from the start
    return c;
}

} // namespace

QStringList TestCliShuoke::args(Bench bench, std::initializer_list<const char *> words) const
{
    QStringList l{QStringLiteral("--family"), QStringLiteral("shuoke")};
    switch (bench) {
    case Rtu:
        l << "--port" << m_rtu.portPath() << "--address"
          << "3";
        break;
    case Ascii:
        l << "--port" << m_ascii.portPath() << "--framing"
          << "ascii"
          << "--address"
          << "4";
        break;
    case Plc:
        l << "--port" << m_plc.portPath() << "--framing"
          << "plc"
          << "--address"
          << "5";
        break;
    case Can:
        l << "--can" << QStringLiteral("virtualcan:") + m_can.interfaceName() << "--address"
          << "6";
        break;
    }
    for (const char *w : words)
        l << QString::fromUtf8(w);
    return l;
}

SimShuokeDrive &TestCliShuoke::sim(Bench bench)
{
    switch (bench) {
    case Rtu: return m_rtu3->drive();
    case Ascii: return m_ascii4->drive();
    case Plc: return m_plc5->drive();
    case Can: break;
    }
    return m_can6->drive();
}

void TestCliShuoke::addBenchRows()
{
    QTest::addColumn<Bench>("bench");
    QTest::newRow("rtu") << Rtu;
    QTest::newRow("ascii") << Ascii;
    QTest::newRow("plc") << Plc;
    QTest::newRow("can") << Can;
}

void TestCliShuoke::initTestCase()
{
    ensureCoreResources();
    QVERIFY(m_dir.isValid());
    QString error;
    // Every function needs these benches: one that cannot start fails (a skip here would hide
    // all of them).
    QVERIFY2(m_rtu.start(&error), qPrintable(error));
    QVERIFY2(m_ascii.start(&error), qPrintable(error));
    QVERIFY2(m_plc.start(&error), qPrintable(error));
    QVERIFY2(m_scan.start(&error), qPrintable(error));
    m_rtu3 = m_rtu.addDrive(driveConfig(3));
    // Drives at different rates on one bus hear each other's traffic as noise; a bus of
    // its own keeps the scan independent of what the other tests sent.
    m_scan.addDrive(driveConfig(3));
    m_scan.addDrive(driveConfig(12, 7));
    m_ascii4 = m_ascii.addDrive(driveConfig(4), SimShuokeSerialDevice::Framing::Ascii);
    m_plc5 = m_plc.addDrive(driveConfig(5), SimShuokeSerialDevice::Framing::Plc);
    QVERIFY2(m_can.start(&error), qPrintable(error));
    m_can6 = m_can.addDrive(driveConfig(6));
    m_can.addDrive(driveConfig(9));
}

void TestCliShuoke::init()
{
    for (Bench b : {Rtu, Ascii, Plc, Can}) {
        sim(b).axis().stop();
        QVERIFY(QTest::qWaitFor([&] { return !sim(b).axis().isRunning(); }, 3000));
    }
}

void TestCliShuoke::infoInEveryFraming_data()
{
    addBenchRows();
}

void TestCliShuoke::infoInEveryFraming()
{
    QFETCH(Bench, bench);
    const CliRun r = runCli(args(bench, {"--json", "info"}));
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    const QJsonObject id = r.json().value("identity").toObject();
    QCOMPARE(id.value("family").toString(), QStringLiteral("shuoke"));
    QCOMPARE(id.value("model").toString(), QStringLiteral("M6505"));
    QVERIFY(r.json().value("capabilities").toArray().contains(QStringLiteral("jog")));
}

void TestCliShuoke::getAndSetInEveryFraming_data()
{
    addBenchRows();
}

void TestCliShuoke::getAndSetInEveryFraming()
{
    QFETCH(Bench, bench);
    sim(bench).setSetting(shuoke::CmdSetMaxSpeed, 12345);
    CliRun r = runCli(args(bench, {"--json", "get", "max-speed", "acceleration"}));
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(r.json().value("parameters").toArray().at(0).toObject().value("value").toInt(), 12345);

    r = runCli(args(bench, {"--json", "set", "max-speed=23456", "acceleration=40000"}));
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(sim(bench).setting(shuoke::CmdSetMaxSpeed), qint64(23456));
    QCOMPARE(sim(bench).setting(shuoke::CmdSetAcceleration), qint64(40000));
    for (const QJsonValue &v : r.json().value("parameters").toArray())
        QCOMPARE(v.toObject().value("result").toString(), QStringLiteral("verified"));
}

void TestCliShuoke::writeOnlySettings()
{
    CliRun r = runCli(args(Rtu, {"--json", "set", "encoder-direction=1"}));
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(sim(Rtu).setting(shuoke::CmdEncoderDirection), qint64(1));
    QCOMPARE(r.json().value("parameters").toArray().at(0).toObject().value("result").toString(),
             QStringLiteral("written-only"));
    r = runCli(args(Rtu, {"get", "encoder-direction"}));
    QCOMPARE(r.exitCode, 0);
    QVERIFY(r.out.contains("not readable"));
}

void TestCliShuoke::setOutOfRangeSendsNothing()
{
    const int before = sim(Rtu).requestCount();
    CliRun r = runCli(args(Rtu, {"--trace", "set", "start-speed=10", "max-speed=100001"}));
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains("max-speed"));
    QCOMPARE(r.txFrames(), 0);
    r = runCli(args(Rtu, {"--trace", "set", "gear-numerator=0"}));
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.txFrames(), 0);
    QTest::qWait(100);
    QCOMPARE(sim(Rtu).requestCount(), before);
}

void TestCliShuoke::backupChangeDiffRestoreVerify_data()
{
    addBenchRows();
}

void TestCliShuoke::backupChangeDiffRestoreVerify()
{
    QFETCH(Bench, bench);
    const QString file = m_dir.filePath(QStringLiteral("shuoke-%1.json").arg(int(bench)));
    CliRun r = runCli(args(bench, {"--json", "backup", "-o"}) << file);
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    BackupFile saved;
    QVERIFY(!saved.load(file));
    QCOMPARE(saved.model(), QStringLiteral("M6505"));
    const qint64 decel = sim(bench).setting(shuoke::CmdSetDeceleration);
    const qint64 stop = sim(bench).setting(shuoke::CmdSetStopSpeed);
    QCOMPARE(saved.values().value(shuoke::CmdSetDeceleration), std::optional<qint64>(decel));

    sim(bench).setSetting(shuoke::CmdSetDeceleration, decel + 100);
    sim(bench).setSetting(shuoke::CmdSetStopSpeed, stop + 7);
    r = runCli(args(bench, {"--json", "diff"}) << file);
    QVERIFY2(r.exitCode == 1, qPrintable(r.text())); // like diff(1): 1 = different
    QCOMPARE(r.json().value("different").toInt(), 2);

    r = runCli(args(bench, {"--json", "restore"}) << file);
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(r.json().value("verified").toArray(),
             (QJsonArray{QStringLiteral("stop-speed"), QStringLiteral("deceleration")}));
    QCOMPARE(sim(bench).setting(shuoke::CmdSetDeceleration), decel);
    QCOMPARE(sim(bench).setting(shuoke::CmdSetStopSpeed), stop);
    r = runCli(args(bench, {"--json", "diff"}) << file);
    QCOMPARE(r.json().value("different").toInt(), 0);
}

void TestCliShuoke::jogStopsWhenItsDurationEnds()
{
    QElapsedTimer t;
    t.start();
    QProcess *p = startCli(args(Rtu, {"--json", "jog", "3000", "--duration", "0.8"}));
    QVERIFY(QTest::qWaitFor([&] { return sim(Rtu).axis().isRunning(); }, 3000));
    const CliRun r = waitCli(p);
    delete p;
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QVERIFY(t.elapsed() >= 800);
    QCOMPARE(r.json().value("stoppedBy").toString(), QStringLiteral("duration"));
    QVERIFY(QTest::qWaitFor([&] { return !sim(Rtu).axis().isRunning(); }, 2000));
}

void TestCliShuoke::jogStopsOnSignal_data()
{
    QTest::addColumn<Bench>("bench");
    QTest::addColumn<int>("signalNumber");
    QTest::newRow("rtu SIGINT") << Rtu << int(SIGINT);
    QTest::newRow("rtu SIGTERM") << Rtu << int(SIGTERM);
    QTest::newRow("can SIGINT") << Can << int(SIGINT);
}

void TestCliShuoke::jogStopsOnSignal()
{
    QFETCH(Bench, bench);
    QFETCH(int, signalNumber);
    QProcess *p = startCli(args(bench, {"--json", "jog", "-2500"}));
    QByteArray seen;
    QVERIFY2(waitForOutput(p, "Ctrl-C", 5000, &seen), seen.constData());
    QVERIFY(QTest::qWaitFor([&] { return sim(bench).axis().isRunning(); }, 3000));
    QTest::qWait(400);
    QVERIFY(sim(bench).axis().isRunning());
    QVERIFY(sim(bench).axis().speed() < 0);
    ::kill(pid_t(p->processId()), signalNumber);
    const CliRun r = waitCli(p, 5000);
    delete p;
    QVERIFY2(r.finished && r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(r.json().value("stoppedBy").toString(), QStringLiteral("signal"));
    QVERIFY(QTest::qWaitFor([&] { return !sim(bench).axis().isRunning(); }, 2000));
}

void TestCliShuoke::moveAndHome()
{
    const qint64 start = sim(Rtu).axis().absolutePosition();
    const qint64 maxSpeed = sim(Rtu).setting(shuoke::CmdSetMaxSpeed);
    QVERIFY(maxSpeed != 8000);
    CliRun r = runCli(args(Rtu, {"--json", "move", "--by", "4000", "--speed", "8000"}));
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QVERIFY(!sim(Rtu).axis().isRunning());
    QCOMPARE(sim(Rtu).axis().absolutePosition(), start + 4000);
    QCOMPARE(r.json().value("reached").toBool(), true);
    // The move ran at 8000 (the seed's moves run at the stored max-speed), and the stored
    // value is back (issue #26).
    QCOMPARE(sim(Rtu).setting(shuoke::CmdSetMaxSpeed), maxSpeed);

    r = runCli(args(Rtu, {"move", "--to", "1000", "--speed", "8000"}));
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QVERIFY(qAbs(sim(Rtu).axis().closedLoopAbsolute() - 1000) <= 1);

    r = runCli(args(Rtu, {"--json", "home"}));
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(r.json().value("finished").toBool(), true);
    QVERIFY(!sim(Rtu).axis().isHoming());
    QVERIFY(!sim(Rtu).axis().homingFailed());
}

// Issue #26: a homing that comes to rest without the origin (stopped at the drive, by
// another master, a STOP) is not "Done": it says so and exits 1.
void TestCliShuoke::aHomingStoppedElsewhereIsNotDone()
{
    const SimShuokeAxis::Switches before = sim(Rtu).axis().switches();
    SimShuokeAxis::Switches far = before;
    far.origin = before.rightLimit - 1000; // a long search
    sim(Rtu).axis().setSwitches(far);
    sim(Rtu).axis().placeAt(before.origin + 5000);
    QProcess *p = startCli(args(Rtu, {"--json", "home", "--positive"}));
    QVERIFY(QTest::qWaitFor([&] { return sim(Rtu).axis().isHoming() && sim(Rtu).axis().isRunning(); }, 10000));
    QTest::qWait(300);
    sim(Rtu).axis().stop(); // stopped outside this program
    const CliRun r = waitCli(p, 15000);
    delete p;
    sim(Rtu).axis().setSwitches(before);
    QVERIFY2(r.finished && r.exitCode == 1, qPrintable(r.text()));
    QVERIFY2(!r.text().contains(QLatin1String("Done")), qPrintable(r.text()));
    QCOMPARE(r.json().value("reached").toBool(true), false);
    QVERIFY2(r.json().value("error").toObject().value("message").toString().contains(
                 QLatin1String("without finding the origin")),
             qPrintable(r.text()));
}

void TestCliShuoke::stopAndEmergencyStop()
{
    sim(Rtu).axis().runSpeed(3000);
    CliRun r = runCli(args(Rtu, {"stop"}));
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QVERIFY(QTest::qWaitFor([&] { return !sim(Rtu).axis().isRunning(); }, 2000));
    sim(Rtu).axis().runSpeed(3000);
    r = runCli(args(Rtu, {"stop", "--emergency"}));
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QVERIFY(QTest::qWaitFor([&] { return !sim(Rtu).axis().isRunning(); }, 500));
}

void TestCliShuoke::monitor()
{
    sim(Can).axis().runSpeed(2000);
    const QString csv = m_dir.filePath(QStringLiteral("shuoke.csv"));
    const CliRun r = runCli(args(Can, {"monitor", "speed,position", "--rate", "10", "--duration", "0.5", "-o"}) << csv);
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QFile f(csv);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    QVERIFY(lines.at(0).startsWith("time_s,speed [pulse/s],position"));
    QVERIFY(lines.size() >= 4);
    QCOMPARE(lines.last().split(',').at(1).toDouble(), 2000.0);
    sim(Can).axis().stop();
}

void TestCliShuoke::unsupportedOperationsExit2()
{
    for (const QStringList &a : {args(Rtu, {"enable", "on"}), args(Rtu, {"ee", "set"}), args(Rtu, {"clear-alarm"})}) {
        const CliRun r = runCli(a);
        QVERIFY2(r.exitCode == 2, qPrintable(a.join(' ') + QStringLiteral(": ") + r.text()));
    }
}

void TestCliShuoke::scanSerialFindsUnknownAddressesAndBauds()
{
    // Drive 12 runs at 19200: neither its address nor its rate is given.
    // A generous probe timeout: the machine running the tests may be busy.
    const CliRun r = runCli({"--family", "shuoke", "--port", m_scan.portPath(), "--json", "--timeout", "120", "scan",
                             "--to", "14", "--bauds", "9600,19200"},
                            120000);
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QMap<int, int> found;
    for (const QJsonValue &v : r.json().value("drives").toArray())
        found.insert(v.toObject().value("address").toInt(), v.toObject().value("baud").toInt());
    QCOMPARE(found.value(3), 9600);
    QCOMPARE(found.value(12), 19200);
    QCOMPARE(found.size(), 2);
}

void TestCliShuoke::scanCan()
{
    const CliRun r = runCli(
        {"--family", "shuoke", "--can", QStringLiteral("virtualcan:") + m_can.interfaceName(), "--json", "scan"});
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QList<int> found;
    for (const QJsonValue &v : r.json().value("drives").toArray())
        found << v.toObject().value("address").toInt();
    std::sort(found.begin(), found.end());
    QCOMPARE(found, (QList<int>{6, 9}));
}

void TestCliShuoke::familyOptions()
{
    // The ASCII drive checks the plain sum (the default); told to send the two's complement
    // the CLI's frames fail the drive's check, and an unknown value is refused up front.
    CliRun r = runCli(
        args(Ascii, {"--option", "shuoke.checksum=twos-complement", "--timeout", "100", "--retries", "0", "info"}));
    QCOMPARE(r.exitCode, 1);
    r = runCli(args(Ascii, {"--option", "shuoke.checksum=sum", "info"}));
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    r = runCli(args(Rtu, {"--trace", "--option", "shuoke.checksum=crc32", "info"}));
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains("shuoke.checksum"));
    QCOMPARE(r.txFrames(), 0);
    // The model, when told, is not probed for.
    r = runCli(args(Rtu, {"--json", "--option", "shuoke.model=M4505S", "info"}));
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(r.json().value("identity").toObject().value("model").toString(), QStringLiteral("M4505S"));
}

QTEST_GUILESS_MAIN(TestCliShuoke)
#include "tst_clishuoke.moc"
