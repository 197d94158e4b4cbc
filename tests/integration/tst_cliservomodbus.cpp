// drivedesk-cli against simulated servo-modbus drives (SimSerialBus on a pty in this
// process, the CLI's real serial/Modbus stack on the other end): every command, the
// backup → change → diff → restore → verify cycle, EEPROM operations, input errors with
// nothing on the wire, scan at unknown addresses and baud rates.
#include "tests/support/clirun.h"

#include "core/common/coreresources.h"
#include "sim/bus/ptyendpoint.h"
#include "sim/bus/simserialbus.h"
#include "sim/servomodbus/simservomodbusdrive.h"
#include "tests/support/requiretool.h"

#include <QTemporaryDir>
#include <QtTest>

#include <memory>

using namespace dd;
using namespace dd::test;

class TestCliServoModbus : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void info();
    void getAndSet();
    void setOutOfRangeSendsNothing();
    void backupChangeDiffRestoreVerify();
    void restoreRefusesOtherFirmwareUnlessForced();
    void corruptBackupSendsNothing();
    void eeOperations();
    void monitor();
    void motionIsNotSupported();
    void wrongBaudTimesOut();
    void scanFindsUnknownAddressesAndBauds();

private:
    QStringList args(std::initializer_list<const char *> words) const;

    QTemporaryDir m_dir;
    std::unique_ptr<SimSerialBus> m_bus;
    SimServoModbusDrive *m_sim = nullptr;    // address 1, 19200 baud (the defaults)
    SimServoModbusDrive *m_hidden = nullptr; // address 23, 38400 baud
    QString m_port;
};

QStringList TestCliServoModbus::args(std::initializer_list<const char *> words) const
{
    QStringList l{
        QStringLiteral("--family"), QStringLiteral("servo-modbus"), QStringLiteral("--port"),    m_port,
        QStringLiteral("--baud"),   QStringLiteral("19200"),        QStringLiteral("--address"), QStringLiteral("1")};
    for (const char *w : words)
        l << QString::fromUtf8(w);
    return l;
}

void TestCliServoModbus::initTestCase()
{
    ensureCoreResources();
    DD_REQUIRE_TOOL(PtyEndpoint::isSupported(), "no pseudo-terminals on this system");
    auto *endpoint = new PtyEndpoint;
    const Error e = endpoint->open();
    QVERIFY2(!e, qPrintable(e.message));
    m_port = endpoint->clientPath();
    m_bus = std::make_unique<SimSerialBus>(endpoint);
    SimServoModbusDrive::Config a;
    a.address = 1;
    a.baud = 19200;
    m_sim = static_cast<SimServoModbusDrive *>(m_bus->addDevice(std::make_unique<SimServoModbusDrive>(a)));
    SimServoModbusDrive::Config b;
    b.address = 23;
    b.baud = 38400;
    m_hidden = static_cast<SimServoModbusDrive *>(m_bus->addDevice(std::make_unique<SimServoModbusDrive>(b)));
}

void TestCliServoModbus::info()
{
    const CliRun r = runCli(args({"--json", "info"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonObject id = r.json().value("identity").toObject();
    QCOMPARE(id.value("family").toString(), QStringLiteral("servo-modbus"));
    QCOMPARE(id.value("firmware").toString(), QStringLiteral("7051"));
    QVERIFY(r.json().value("capabilities").toArray().contains(QStringLiteral("ee-operations")));
}

void TestCliServoModbus::getAndSet()
{
    m_sim->setParameter(12, 321);
    CliRun r = runCli(args({"--json", "get", "PA12", "13", "P51"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    const QJsonArray list = r.json().value("parameters").toArray();
    QCOMPARE(list.size(), 3);
    QCOMPARE(list.at(0).toObject().value("value").toInt(), 321);
    QCOMPARE(list.at(0).toObject().value("key").toString(), QStringLiteral("PA12"));
    QCOMPARE(list.at(2).toObject().value("value").toInt(), 1); // PA51 = address

    r = runCli(args({"set", "PA12=400", "PA13=-12"}));
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY(r.out.contains("verified"));
    QCOMPARE(m_sim->parameter(12), quint16(400));
    QCOMPARE(qint16(m_sim->parameter(13)), qint16(-12));
    QVERIFY(r.err.contains("ee set")); // the hint that the values are only in RAM
}

void TestCliServoModbus::setOutOfRangeSendsNothing()
{
    const quint64 bytes = m_bus->stats().bytesIn;
    const quint16 before = m_sim->parameter(12);
    CliRun r = runCli(args({"--trace", "set", "PA12=5", "PA14=70000"}));
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.txFrames(), 0);
    r = runCli(args({"--trace", "set", "PA2=7000"})); // read-only
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.txFrames(), 0);
    QTest::qWait(50);
    QCOMPARE(m_bus->stats().bytesIn, bytes);
    QCOMPARE(m_sim->parameter(12), before);
}

void TestCliServoModbus::backupChangeDiffRestoreVerify()
{
    const QString file = m_dir.filePath(QStringLiteral("pa.json"));
    const auto original = m_sim->parameters();
    CliRun r = runCli(args({"backup", "-o"}) << file);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QVERIFY(r.out.contains("60 parameter"));

    m_sim->setParameter(20, quint16(original[20] + 5));
    m_sim->setParameter(33, quint16(original[33] + 1));
    r = runCli(args({"diff"}) << file);
    QVERIFY2(r.exitCode == 1, r.err.constData()); // like diff(1): 1 = different
    QVERIFY(r.out.contains("PA20"));
    QVERIFY(r.out.contains("PA33"));
    QVERIFY(r.out.contains("2 differ"));

    r = runCli(args({"--json", "restore", "--dry-run"}) << file);
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(m_sim->parameter(20), quint16(original[20] + 5));

    r = runCli(args({"--json", "restore"}) << file);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(r.json().value("verified").toArray(), (QJsonArray{QStringLiteral("PA20"), QStringLiteral("PA33")}));
    QCOMPARE(m_sim->parameters(), original);
    r = runCli(args({"--json", "diff"}) << file);
    QCOMPARE(r.json().value("different").toInt(), 0);
}

void TestCliServoModbus::restoreRefusesOtherFirmwareUnlessForced()
{
    const QString file = m_dir.filePath(QStringLiteral("fw.json"));
    QCOMPARE(runCli(args({"backup", "-o"}) << file).exitCode, 0);
    const quint16 p20 = m_sim->parameter(20);
    m_sim->setParameter(20, quint16(p20 + 1));
    m_sim->setFirmware(7060);
    CliRun r = runCli(args({"restore"}) << file);
    QCOMPARE(r.exitCode, 2);
    QVERIFY(r.err.contains("7060"));
    QCOMPARE(m_sim->parameter(20), quint16(p20 + 1));
    r = runCli(args({"restore", "--force"}) << file);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QCOMPARE(m_sim->parameter(20), p20);
    m_sim->setFirmware(7051);
}

void TestCliServoModbus::corruptBackupSendsNothing()
{
    const QString file = m_dir.filePath(QStringLiteral("bad.json"));
    QCOMPARE(runCli(args({"backup", "-o"}) << file).exitCode, 0);
    QFile f(file);
    QVERIFY(f.open(QIODevice::ReadWrite));
    const QByteArray bytes = f.readAll();
    f.resize(0);
    f.write(bytes.left(bytes.size() - 40)); // truncated
    f.close();
    const quint64 in = m_bus->stats().bytesIn;
    const CliRun r = runCli(args({"--trace", "restore"}) << file);
    QCOMPARE(r.exitCode, 2);
    QCOMPARE(r.txFrames(), 0);
    QTest::qWait(50);
    QCOMPARE(m_bus->stats().bytesIn, in);
}

void TestCliServoModbus::eeOperations()
{
    m_sim->setParameter(40, 1111);
    const int done = m_sim->eeOperationsCompleted();
    CliRun r = runCli(args({"--json", "ee", "set"}));
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(r.json().value("operation").toString(), QStringLiteral("EE-Set"));
    QCOMPARE(m_sim->eepromParameter(40), quint16(1111));
    QCOMPARE(m_sim->eeOperationsCompleted(), done + 1);

    m_sim->setParameter(40, 2222);
    r = runCli(args({"ee", "rd"})); // reload from EEPROM: the unsaved change is gone
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(m_sim->parameter(40), quint16(1111));

    // The legacy format (PA2 < 7050) polls until the drive reports completion.
    m_sim->setFirmware(7040);
    m_sim->setParameter(41, 77);
    r = runCli(args({"ee", "EE-Set"}));
    QVERIFY2(r.exitCode == 0, qPrintable(r.text()));
    QCOMPARE(m_sim->eepromParameter(41), quint16(77));
    m_sim->setFirmware(7051);
}

void TestCliServoModbus::monitor()
{
    const QString csv = m_dir.filePath(QStringLiteral("dp.csv"));
    CliRun r = runCli(
        args({"monitor", "speed,torque,current,position-error", "--rate", "10", "--duration", "0.45", "-o"}) << csv);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QFile f(csv);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    QVERIFY(lines.at(0).startsWith("time_s,speed [r/min],torque"));
    QVERIFY(lines.size() >= 4);
    r = runCli(args({"monitor", "temperature"})); // not a DP register
    QCOMPARE(r.exitCode, 2);
}

void TestCliServoModbus::motionIsNotSupported()
{
    for (const char *command : {"jog", "move", "enable", "clear-alarm", "home", "stop"}) {
        QStringList a = args({command});
        if (qstrcmp(command, "jog") == 0)
            a << QStringLiteral("100");
        else if (qstrcmp(command, "move") == 0)
            a << QStringLiteral("--by") << QStringLiteral("10");
        else if (qstrcmp(command, "enable") == 0)
            a << QStringLiteral("on");
        const CliRun r = runCli(a);
        QVERIFY2(r.exitCode == 2, qPrintable(QStringLiteral("%1: %2 %3").arg(command).arg(r.exitCode).arg(r.text())));
        QVERIFY(!r.err.trimmed().isEmpty());
    }
}

void TestCliServoModbus::wrongBaudTimesOut()
{
    const CliRun r = runCli(
        {"--family", "servo-modbus", "--port", m_port, "--baud", "9600", "--timeout", "50", "--retries", "0", "info"});
    QCOMPARE(r.exitCode, 1);
    QVERIFY(r.err.contains("scan")); // the hint
}

void TestCliServoModbus::scanFindsUnknownAddressesAndBauds()
{
    // Neither the address nor the baud rate of the second drive is given anywhere. (A
    // generous probe timeout: the test machine may be busy; the range keeps it short.)
    const CliRun r = runCli({"--family", "servo-modbus", "--port", m_port, "--json", "--timeout", "60", "scan", "--to",
                             "30", "--bauds", "9600,19200,38400,57600"},
                            120000);
    QVERIFY2(r.exitCode == 0, r.err.constData());
    QMap<int, int> found;
    for (const QJsonValue &v : r.json().value("drives").toArray())
        found.insert(v.toObject().value("address").toInt(), v.toObject().value("baud").toInt());
    QCOMPARE(found.value(1), 19200);
    QCOMPARE(found.value(23), 38400);
    QCOMPARE(found.size(), 2);

    const CliRun none = runCli(
        {"--family", "servo-modbus", "--port", m_port, "scan", "--from", "2", "--to", "5", "--bauds", "19200"});
    QCOMPARE(none.exitCode, 1);
    QVERIFY(none.err.contains("No drive answered"));
}

QTEST_GUILESS_MAIN(TestCliServoModbus)
#include "tst_cliservomodbus.moc"
