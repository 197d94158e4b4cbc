// drivedesk-cli against simulated servo-can drives (SimCanBus on a private virtualcan hub in
// this process): every command, the backup → change → diff → restore → verify cycle, input
// errors with nothing on the wire, jog ending by duration, SIGINT and SIGTERM, scan.
#include "tests/support/clirun.h"

#include "core/common/coreresources.h"
#include "core/params/backupfile.h"
#include "sim/bus/simcanbus.h"
#include "sim/bus/virtualcanhub.h"
#include "sim/servocan/simservocandrive.h"

#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <memory>

using namespace dd;
using namespace dd::test;

class TestCliServoCan : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void init();
    void info();
    void getAndSet();
    void setOutOfRangeSendsNothing();
    void backupChangeDiffRestoreVerify();
    void restoreDryRunAndOnly();
    void corruptBackupSendsNothing();
    void monitorCsvAndJson();
    void jogStopsWhenItsDurationEnds();
    void jogStopsOnSignal_data();
    void jogStopsOnSignal();
    void moveWaitsForTheEnd();
    void moveStoppedByAnotherProgramIsNotDone();
    void enableStopClearAlarm();
    void unsupportedOperationsExit2();
    void scanFindsStations();
    void channels();
    // Last: the drive's watchdog trip leaves the simulated drive in a state the tests above
    // do not expect.
    void jogSaysTheWatchdogStopsASilentDrive();

private:
    QStringList args(std::initializer_list<const char *> words, int station = 1) const;
    bool waitIdle(SimServoCanDrive *d, int ms = 3000);

    QTemporaryDir m_dir;
    std::unique_ptr<VirtualCanHub> m_hub;
    std::unique_ptr<SimCanBus> m_bus;
    SimServoCanDrive *m_sim1 = nullptr;
    SimServoCanDrive *m_sim7 = nullptr;
    QString m_can;
};

QStringList TestCliServoCan::args(std::initializer_list<const char *> words, int station) const
{
    QStringList l{QStringLiteral("--family"),  QStringLiteral("servo-can"), QStringLiteral("--can"), m_can,
                  QStringLiteral("--address"), QString::number(station)};
    for (const char *w : words)
        l << QString::fromUtf8(w);
    return l;
}

bool TestCliServoCan::waitIdle(SimServoCanDrive *d, int ms)
{
    QElapsedTimer t;
    t.start();
    while (d->motor().isMoving() && t.elapsed() < ms)
        QTest::qWait(10);
    return !d->motor().isMoving();
}

void TestCliServoCan::initTestCase()
{
    ensureCoreResources();
    QVERIFY(m_dir.isValid());
    m_hub = std::make_unique<VirtualCanHub>();
    QVERIFY(m_hub->start());
    m_can = QStringLiteral("virtualcan:") + m_hub->interfaceName(0);
    m_bus = std::make_unique<SimCanBus>();
    m_sim1 = static_cast<SimServoCanDrive *>(m_bus->addDevice(std::make_unique<SimServoCanDrive>(1)));
    m_sim7 = static_cast<SimServoCanDrive *>(m_bus->addDevice(std::make_unique<SimServoCanDrive>(7)));
    const Error e = m_bus->open(QStringLiteral("virtualcan"), m_hub->interfaceName(0));
    QVERIFY2(!e, qPrintable(e.message));
    QTRY_VERIFY_WITH_TIMEOUT(m_bus->isConnected(), 5000);
}

void TestCliServoCan::init()
{
    for (SimServoCanDrive *d : {m_sim1, m_sim7}) {
        d->motor().stop();
        QVERIFY(waitIdle(d));
        if (d->alarmCode())
            d->motor().clearAlarm();
    }
}

void TestCliServoCan::info()
{
    const CliRun r = runCli(args({"--json", "info"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonObject doc = r.json();
    QCOMPARE(doc.value("ok").toBool(), true);
    const QJsonObject id = doc.value("identity").toObject();
    QCOMPARE(id.value("family").toString(), QStringLiteral("servo-can"));
    QCOMPARE(id.value("address").toInt(), 1);
    QVERIFY(doc.value("capabilities").toArray().contains(QStringLiteral("jog")));
    QCOMPARE(doc.value("status").toObject().value("alarm").toInt(), 0);

    const CliRun text = runCli(args({"info"}));
    QCOMPARE(text.exitCode, 0);
    QVERIFY(text.out.contains("servo-can"));
    QVERIFY(text.out.contains("Capabilities"));
}

void TestCliServoCan::getAndSet()
{
    const qint16 p4 = m_sim1->parameter(4);
    const qint16 p100 = m_sim1->parameter(100);
    CliRun r = runCli(args({"--json", "get", "P4", "100", "P75"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonArray list = r.json().value("parameters").toArray();
    QCOMPARE(list.size(), 3);
    QCOMPARE(list.at(0).toObject().value("value").toInt(), int(p4));
    QCOMPARE(list.at(1).toObject().value("value").toInt(), int(p100));
    QCOMPARE(list.at(2).toObject().value("value").toInt(), 1);

    r = runCli(args({"--json", "set", "P100=1234", "P101=-77"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(m_sim1->parameter(100), qint16(1234));
    QCOMPARE(m_sim1->parameter(101), qint16(-77));
    for (const QJsonValue &v : r.json().value("parameters").toArray())
        QCOMPARE(v.toObject().value("result").toString(), QStringLiteral("verified"));

    // A drive that does not take the value: written, read back different → exit 1.
    m_sim1->setWriteProtected(102, true);
    const qint16 old = m_sim1->parameter(102);
    r = runCli(args({"--json", "set", "P102=999"}));
    m_sim1->setWriteProtected(102, false);
    QCOMPARE(r.exitCode, 1);
    QCOMPARE(m_sim1->parameter(102), old);
    const QJsonObject p = r.json().value("parameters").toArray().at(0).toObject();
    QCOMPARE(p.value("result").toString(), QStringLiteral("mismatch"));
    QCOMPARE(p.value("readBack").toInt(), int(old));
    QCOMPARE(r.json().value("error").toObject().value("code").toString(), QStringLiteral("verify-mismatch"));
}

void TestCliServoCan::setOutOfRangeSendsNothing()
{
    const quint64 before = m_sim1->stats().framesForUs;
    const quint64 writes = m_sim1->stats().parameterWrites;
    // P100 is int16: 40000 does not fit; the good value beside it is not written either.
    const CliRun r = runCli(args({"--trace", "set", "P101=5", "P100=40000"}));
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains("P100"));
    QCOMPARE(r.txFrames(), 0);
    QTest::qWait(50);
    QCOMPARE(m_sim1->stats().framesForUs, before);
    QCOMPARE(m_sim1->stats().parameterWrites, writes);
}

void TestCliServoCan::backupChangeDiffRestoreVerify()
{
    const QString file = m_dir.filePath(QStringLiteral("cycle.json"));
    const auto original = m_sim1->parameters();
    CliRun r = runCli(args({"--json", "backup", "-o"}) << file);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(r.json().value("parameters").toInt(), 220);
    BackupFile saved;
    QVERIFY(!saved.load(file));
    QCOMPARE(saved.family(), std::optional<Family>(Family::ServoCan));
    QCOMPARE(saved.values().value(100), std::optional<qint64>(original[100]));

    // Change three parameters on the drive behind the tool's back.
    m_sim1->setParameter(100, qint16(original[100] + 11));
    m_sim1->setParameter(150, qint16(original[150] - 3));
    m_sim1->setParameter(219, qint16(original[219] + 1));

    r = runCli(args({"--json", "diff"}) << file);
    QVERIFY2(r.exitCode == 1, r.err.constData()); // like diff(1): 1 = different
    QCOMPARE(r.json().value("different").toInt(), 3);
    QStringList differing;
    for (const QJsonValue &v : r.json().value("parameters").toArray())
        if (v.toObject().value("status").toString() == QLatin1String("different"))
            differing << v.toObject().value("key").toString();
    QCOMPARE(differing, (QStringList{"P100", "P150", "P219"}));

    const quint64 writesBefore = m_sim1->stats().parameterWrites;
    m_sim1->stats().writtenIndexes.clear();
    r = runCli(args({"--json", "restore"}) << file);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    // Only the differences are written (a write whose answer came late may be sent again:
    // seen under ASan).
    QCOMPARE(m_sim1->stats().writtenIndexes, (QSet<int>{100, 150, 219}));
    QVERIFY(m_sim1->stats().parameterWrites - writesBefore <= 9);
    QCOMPARE(m_sim1->parameters(), original);
    const QJsonObject doc = r.json();
    QCOMPARE(doc.value("verified").toArray().size(), 3);
    QVERIFY(doc.value("notWritten").toArray().isEmpty());

    r = runCli(args({"--json", "diff"}) << file);
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.json().value("different").toInt(), 0);

    // A restore that cannot verify says exactly what was written and what not.
    m_sim1->setParameter(120, qint16(original[120] + 5));
    m_sim1->setParameter(130, qint16(original[130] + 5));
    m_sim1->setWriteProtected(130, true);
    r = runCli(args({"--json", "restore"}) << file);
    m_sim1->setWriteProtected(130, false);
    QCOMPARE(r.exitCode, 1);
    const QJsonObject bad = r.json();
    QCOMPARE(bad.value("ok").toBool(true), false);
    QCOMPARE(bad.value("verified").toArray(), QJsonArray{QStringLiteral("P120")});
    QCOMPARE(bad.value("mismatch").toArray(), QJsonArray{QStringLiteral("P130")});
    QVERIFY(r.err.contains("P130"));
    m_sim1->setParameter(130, original[130]);

    // Text mode lists the written and the unwritten ones by name.
    m_sim1->setParameter(130, qint16(original[130] + 5));
    m_sim1->setWriteProtected(130, true);
    r = runCli(args({"restore"}) << file);
    m_sim1->setWriteProtected(130, false);
    QCOMPARE(r.exitCode, 1);
    QVERIFY(r.out.contains("Written:"));
    m_sim1->setParameter(130, original[130]);
}

void TestCliServoCan::restoreDryRunAndOnly()
{
    const QString file = m_dir.filePath(QStringLiteral("only.json"));
    QCOMPARE(runCli(args({"backup", "-o"}) << file).exitCode, 0);
    const auto original = m_sim1->parameters();
    m_sim1->setParameter(10, qint16(original[10] + 1));
    m_sim1->setParameter(11, qint16(original[11] + 1));

    const quint64 writes = m_sim1->stats().parameterWrites;
    CliRun r = runCli(args({"--json", "restore", "--dry-run"}) << file);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(r.json().value("selected").toArray().size(), 2);
    QCOMPARE(m_sim1->stats().parameterWrites, writes);

    r = runCli(args({"restore", "--only", "P11"}) << file);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(m_sim1->parameter(11), original[11]);
    QCOMPARE(m_sim1->parameter(10), qint16(original[10] + 1));
    m_sim1->setParameter(10, original[10]);

    // A backup of station 1 onto station 7 works (same family, no firmware to differ).
    m_sim7->setParameter(12, qint16(m_sim1->parameter(12) + 9));
    r = runCli(args({"restore"}, 7) << file);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(m_sim7->parameter(12), m_sim1->parameter(12));
}

void TestCliServoCan::corruptBackupSendsNothing()
{
    const QString file = m_dir.filePath(QStringLiteral("corrupt.json"));
    QCOMPARE(runCli(args({"backup", "-o"}) << file).exitCode, 0);
    QFile f(file);
    QVERIFY(f.open(QIODevice::ReadWrite));
    QByteArray bytes = f.readAll();
    const qsizetype at = bytes.indexOf("\"value\"");
    QVERIFY(at > 0);
    bytes.insert(at + 9, '1'); // a digit more in one value: the checksum no longer fits
    f.resize(0);
    f.write(bytes);
    f.close();
    const quint64 before = m_sim1->stats().framesForUs;
    for (const char *command : {"restore", "diff"}) {
        const CliRun r = runCli(args({"--trace", command}) << file);
        QVERIFY2(r.exitCode == 2, qPrintable(r.text()));
        QCOMPARE(r.txFrames(), 0);
    }
    QTest::qWait(50);
    QCOMPARE(m_sim1->stats().framesForUs, before);
}

void TestCliServoCan::monitorCsvAndJson()
{
    m_sim1->motor().enable();
    m_sim1->motor().runSpeed(100000);
    const QString csv = m_dir.filePath(QStringLiteral("m.csv"));
    CliRun r = runCli(args({"monitor", "speed,position,bus-voltage", "--rate", "20", "--duration", "0.5", "-o"})
                      << csv);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QFile f(csv);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    QCOMPARE(lines.at(0), QByteArray("time_s,speed [r/min],position [pulses],bus-voltage [V]"));
    QVERIFY2(lines.size() >= 5, QByteArray::number(lines.size()).constData());
    const QList<QByteArray> row = lines.last().split(',');
    QCOMPARE(row.size(), 4);
    QVERIFY(row.at(0).toDouble() > 0.1 && row.at(0).toDouble() < 1.0);
    QVERIFY(qAbs(row.at(1).toDouble() - 600) < 60); // 100000 counts/s = 600 r/min
    QVERIFY(r.out.contains("samples written"));

    r = runCli(args({"--json", "monitor", "speed", "--rate", "50", "--duration", "0.3"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QList<QJsonObject> docs = r.jsonLines();
    QVERIFY(docs.size() >= 4);
    QVERIFY(docs.first().contains("time"));
    QVERIFY(docs.first().contains("speed"));
    QCOMPARE(docs.last().value("ok").toBool(), true);
    QCOMPARE(docs.last().value("samples").toInt(), docs.size() - 1);

    r = runCli(args({"monitor", "speed,flux-capacitor", "--duration", "0.1"}));
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains("flux-capacitor"));
    m_sim1->motor().stop();
}

void TestCliServoCan::jogStopsWhenItsDurationEnds()
{
    const quint64 trips = m_sim1->stats().watchdogTrips;
    QElapsedTimer t;
    t.start();
    QProcess *p = startCli(args({"--json", "jog", "300", "--duration", "0.6", "--enable"}));
    QVERIFY(QTest::qWaitFor([&] { return m_sim1->motor().isMoving(); }, 3000));
    const CliRun r = waitCli(p);
    delete p;
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QVERIFY(t.elapsed() >= 600);
    const QJsonObject doc = r.json();
    QCOMPARE(doc.value("stoppedBy").toString(), QStringLiteral("duration"));
    QCOMPARE(doc.value("axisStoppedBy").toString(), QStringLiteral("command"));
    QVERIFY(doc.value("seconds").toDouble() >= 0.59);
    QVERIFY(waitIdle(m_sim1, 1000)); // stopped by the CLI, not by the 2 s watchdog
    QCOMPARE(m_sim1->stats().watchdogTrips, trips);
}

void TestCliServoCan::jogSaysTheWatchdogStopsASilentDrive()
{
    // The drive loses power mid-jog: the stop cannot be confirmed, and the CLI says that
    // the drive's own watchdog stops the axis (servo-can has one), exit 1.
    QProcess *p = startCli(args({"--json", "jog", "300", "--duration", "0.5", "--enable"}));
    QVERIFY(QTest::qWaitFor([&] { return m_sim1->motor().isMoving(); }, 3000));
    m_sim1->faults().setSilent(true);
    const CliRun r = waitCli(p);
    delete p;
    m_sim1->faults().setSilent(false);
    QCOMPARE(r.exitCode, 1);
    const QJsonObject doc = r.json();
    QCOMPARE(doc.value("axisStoppedBy").toString(), QStringLiteral("drive-watchdog"));
    QCOMPARE(doc.value("stopped").toBool(), false);
    QVERIFY2(doc.value("error").toObject().value("message").toString().contains("watchdog"), qPrintable(r.text()));
    QVERIFY(waitIdle(m_sim1, 4000)); // the simulated drive's 2 s watchdog
    // The watchdog's ramp leaves the model between two counts: put it back on a whole count
    // (a real encoder has no fractions), as the tests after this one expect.
    m_sim1->motor().setPosition(m_sim1->motor().position());
}

void TestCliServoCan::jogStopsOnSignal_data()
{
    QTest::addColumn<int>("signalNumber");
    QTest::newRow("SIGINT") << int(SIGINT);
    QTest::newRow("SIGTERM") << int(SIGTERM);
}

void TestCliServoCan::jogStopsOnSignal()
{
    QFETCH(int, signalNumber);
    const quint64 trips = m_sim1->stats().watchdogTrips;
    QProcess *p = startCli(args({"--json", "jog", "-200", "--enable"}));
    QByteArray seen;
    QVERIFY2(waitForOutput(p, "Ctrl-C", 5000, &seen), seen.constData());
    QVERIFY(QTest::qWaitFor([&] { return m_sim1->motor().isMoving(); }, 3000));
    QTest::qWait(300); // several lease renewals: still running
    QVERIFY(m_sim1->motor().isMoving());
    QVERIFY(m_sim1->motor().speed() < 0);
    ::kill(pid_t(p->processId()), signalNumber);
    const CliRun r = waitCli(p, 5000);
    delete p;
    QVERIFY2(r.finished && r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(r.json().value("stoppedBy").toString(), QStringLiteral("signal"));
    QVERIFY(waitIdle(m_sim1, 1000));
    QCOMPARE(m_sim1->stats().watchdogTrips, trips);
}

void TestCliServoCan::moveWaitsForTheEnd()
{
    const qint64 start = m_sim1->motor().position();
    CliRun r = runCli(args({"--json", "move", "--by", "20000", "--speed", "600", "--enable"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY(!m_sim1->motor().isMoving());
    QCOMPARE(m_sim1->motor().position(), start + 20000);
    QCOMPARE(r.json().value("position").toInt(), int(start + 20000));

    r = runCli(args({"move", "--to", "-5000", "--speed", "600", "--enable"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(m_sim1->motor().position(), qint64(-5000));
}

// Issue #26: a move that another program stops ("drivedesk-cli stop" from a second shell,
// the GUI's STOP) comes to rest short of its target: not "Done", but where it stopped and how
// far short, exit 1.
void TestCliServoCan::moveStoppedByAnotherProgramIsNotDone()
{
    const qint64 start = m_sim1->motor().position();
    std::unique_ptr<QProcess> move(startCli(args({"--json", "move", "--by", "3000000", "--speed", "300", "--enable"})));
    QVERIFY(move->waitForStarted(10000));
    QVERIFY(QTest::qWaitFor([&] { return m_sim1->motor().isMoving(); }, 15000));
    // Both processes talk to the simulated drive of this process: its event loop must run.
    std::unique_ptr<QProcess> stop(startCli(args({"stop"})));
    QVERIFY(QTest::qWaitFor([&] { return stop->state() == QProcess::NotRunning; }, 20000));
    QCOMPARE(stop->exitCode(), 0);
    QVERIFY(QTest::qWaitFor([&] { return move->state() == QProcess::NotRunning; }, 20000));
    const QByteArray out = move->readAllStandardOutput();
    const QByteArray err = move->readAllStandardError();
    QCOMPARE(move->exitCode(), 1);
    QVERIFY2(!out.contains("Done") && !err.contains("Done"), out.constData());
    const QJsonObject doc = QJsonDocument::fromJson(out).object();
    QCOMPARE(doc.value("ok").toBool(), false);
    QVERIFY2(!doc.value("reached").toBool(true), out.constData());
    QCOMPARE(qint64(doc.value("target").toDouble()), start + 3000000);
    const qint64 at = qint64(doc.value("position").toDouble());
    QVERIFY(at > start && at < start + 3000000);
    QCOMPARE(qint64(doc.value("distanceToTarget").toDouble()), start + 3000000 - at);
    const QString message = doc.value("error").toObject().value("message").toString();
    QVERIFY2(message.contains(QLatin1String("short of the target")), qPrintable(message));
    QCOMPARE(doc.value("error").toObject().value("code").toString(), QStringLiteral("cancelled"));
}

void TestCliServoCan::enableStopClearAlarm()
{
    CliRun r = runCli(args({"enable", "on"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY(QTest::qWaitFor([&] { return m_sim1->motor().isEnabled(); }, 1000));
    r = runCli(args({"enable", "off"}));
    QCOMPARE(r.exitCode, 0);
    QVERIFY(QTest::qWaitFor([&] { return !m_sim1->motor().isEnabled(); }, 1000));

    m_sim1->motor().enable();
    m_sim1->motor().runSpeed(50000);
    r = runCli(args({"stop"}));
    QCOMPARE(r.exitCode, 0);
    QVERIFY(waitIdle(m_sim1, 1000));
    QVERIFY(m_sim1->motor().isEnabled()); // 0x26 keeps the servo enabled

    m_sim1->motor().runSpeed(50000);
    r = runCli(args({"stop", "--emergency"}));
    QCOMPARE(r.exitCode, 0);
    QVERIFY(waitIdle(m_sim1, 1000));
    QVERIFY(QTest::qWaitFor([&] { return !m_sim1->motor().isEnabled(); }, 1000));

    m_sim1->injectAlarm(12);
    r = runCli(args({"--json", "info"}));
    QCOMPARE(r.json().value("status").toObject().value("alarm").toInt(), 12);
    QVERIFY(r.json().value("status").toObject().value("alarmText").toString().contains(QLatin1String("12")));
    r = runCli(args({"clear-alarm"}));
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(m_sim1->alarmCode(), 0);
}

void TestCliServoCan::unsupportedOperationsExit2()
{
    // servo-can has no homing and no EEPROM operations.
    CliRun r = runCli(args({"home"}));
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains("homing"));
    r = runCli(args({"ee", "set"}));
    QCOMPARE(r.exitCode, 2);
    // A move needs a positioning speed on this family.
    r = runCli(args({"move", "--by", "100", "--enable"}));
    QCOMPARE(r.exitCode, 2);
    QVERIFY(!m_sim1->motor().isMoving());
}

void TestCliServoCan::scanFindsStations()
{
    const CliRun r = runCli({"--family", "servo-can", "--can", m_can, "--json", "scan"});
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QList<int> found;
    for (const QJsonValue &v : r.json().value("drives").toArray()) {
        QCOMPARE(v.toObject().value("family").toString(), QStringLiteral("servo-can"));
        found << v.toObject().value("address").toInt();
    }
    std::sort(found.begin(), found.end());
    QCOMPARE(found, (QList<int>{1, 7}));

    const CliRun some = runCli({"--family", "servo-can", "--can", m_can, "scan", "--from", "5", "--to", "9"});
    QCOMPARE(some.exitCode, 0);
    QVERIFY(some.out.contains("address 7"));
    QVERIFY(!some.out.contains("address 1 "));
}

void TestCliServoCan::channels()
{
    const CliRun r = runCli(args({"--json", "channels"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QStringList ids;
    for (const QJsonValue &v : r.json().value("channels").toArray())
        ids << v.toObject().value("id").toString();
    for (const char *id : {"speed", "torque", "current", "bus-voltage", "position", "position-error", "temperature"})
        QVERIFY2(ids.contains(QLatin1String(id)), id);
}

QTEST_GUILESS_MAIN(TestCliServoCan)
#include "tst_cliservocan.moc"
