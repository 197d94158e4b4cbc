// The servo-modbus family end to end: ServoModbusBackend (ModbusLink on
// SerialLink) over a pty against SimServoModbusDrive on a SimSerialBus, which
// models the wire time, the baud rate and faults.

#include "core/drive/servomodbus/servomodbusbackend.h"
#include "core/drive/servomodbus/servomodbusdrive.h"
#include "core/drive/servomodbus/servomodbusscanner.h"
#include "core/link/modbuslink.h"
#include "core/link/traffictap.h"
#include "core/protocol/familytraits.h"
#include "core/protocol/modbus/crc16.h"
#include "core/protocol/servomodbus/servomodbus.h"
#include "sim/bus/ptyendpoint.h"
#include "sim/bus/simserialbus.h"
#include "sim/servomodbus/simservomodbusdrive.h"
#include "tests/support/replywait.h"
#include "tests/support/requiretool.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QtTest>
#include <memory>

using namespace dd;

namespace {

template <typename R>
bool waitDone(R *r, int ms = 10000)
{
    return test::waitInEventLoop(r, ms);
}

void spin(int ms)
{
    QEventLoop loop;
    QTimer::singleShot(ms, &loop, &QEventLoop::quit);
    loop.exec();
}

// A pty, a bus with simulated drives, and the backend on the host side.
struct Bench
{
    SimSerialBus *bus = nullptr;
    PtyEndpoint *pty = nullptr;
    QList<SimServoModbusDrive *> drives;
    TrafficTap tap;
    QList<TrafficRecord> records;
    std::unique_ptr<ServoModbusBackend> backend;

    explicit Bench(QList<SimServoModbusDrive::Config> configs)
    {
        pty = new PtyEndpoint;
        if (pty->open().isError())
            return;
        bus = new SimSerialBus(pty);
        for (const auto &c : configs)
            drives << static_cast<SimServoModbusDrive *>(bus->addDevice(std::make_unique<SimServoModbusDrive>(c)));
        QObject::connect(&tap, &TrafficTap::frameRecorded, &tap, [this](const TrafficRecord &r) { records << r; });
    }
    ~Bench()
    {
        backend.reset();
        delete bus;
    }

    bool open(int baud, QVariantMap options = {}, int timeoutMs = -1, int retries = -1)
    {
        ConnectionSettings cs;
        cs.family = Family::ServoModbus;
        cs.port = pty->clientPath();
        cs.baud = baud;
        cs.options = options;
        cs.timeoutMs = timeoutMs;
        cs.retries = retries;
        backend = std::make_unique<ServoModbusBackend>();
        Error e;
        const bool ok = backend->open(cs, &tap, &e);
        if (!ok)
            qWarning() << e.message;
        return ok;
    }

    ServoModbusDrive *drive(int address) { return static_cast<ServoModbusDrive *>(backend->drive(address)); }
    int txCount() const
    {
        return int(std::count_if(records.begin(), records.end(),
                                 [](const TrafficRecord &r) { return r.direction == TrafficRecord::Direction::Tx; }));
    }
    QList<QByteArray> txFrames() const
    {
        QList<QByteArray> out;
        for (const auto &r : records)
            if (r.direction == TrafficRecord::Direction::Tx)
                out << r.bytes;
        return out;
    }
};

SimServoModbusDrive::Config driveConfig(int address, int baud, quint16 firmware = 7051)
{
    SimServoModbusDrive::Config c;
    c.address = address;
    c.baud = baud;
    c.firmware = firmware;
    return c;
}

QList<int> allParameters()
{
    QList<int> all;
    for (int n = 0; n < servomodbus::ParameterCount; ++n)
        all << n;
    return all;
}

} // namespace

class TestServoModbusDrive : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase() { DD_REQUIRE_TOOL(PtyEndpoint::isSupported(), "no pseudo-terminals on this platform"); }

    void identityReadsFirmwareAndAddress()
    {
        Bench b({driveConfig(3, 19200)});
        QVERIFY(b.open(0)); // family default: 19200
        QCOMPARE(b.backend->link()->settings().baud, familyTraits(Family::ServoModbus).defaultBaud);
        ServoModbusDrive *d = b.drive(3);
        DriveReply *r = d->refreshIdentity();
        QVERIFY(waitDone(r));
        QVERIFY2(r->ok(), qPrintable(r->error().message));
        QCOMPARE(d->identity().firmware, QStringLiteral("7051"));
        QCOMPARE(r->info().value("pa51").toInt(), 3);
        QCOMPARE(r->info().value("eeFormat").toString(), QStringLiteral("new"));
        QCOMPARE(b.txCount(), 2); // PA2 and PA51 are 49 registers apart: two requests
    }

    void backupOfAllParametersTakesThreeRequests()
    {
        Bench b({driveConfig(1, 115200)});
        QVERIFY(b.open(115200));
        b.drives[0]->setParameter(17, quint16(-1234));
        DriveReply *r = b.drive(1)->readParameters(allParameters());
        QSignalSpy progress(r, &DriveReply::progress);
        QVERIFY(waitDone(r));
        QVERIFY2(r->ok(), qPrintable(r->error().message));
        QCOMPARE(progress.size(), 3);
        QCOMPARE(progress.last().at(0).toInt(), 3);
        QCOMPARE(r->parameters().size(), 60);
        for (int n = 0; n < 60; ++n)
            QCOMPARE(r->parameters().value(n), qint64(qint16(b.drives[0]->parameter(n))));
        QCOMPARE(r->parameters().value(17), qint64(-1234));
        const QList<QByteArray> tx = b.txFrames();
        QCOMPARE(tx.size(), 3);
        QCOMPARE(tx[0], withCrc16(QByteArray::fromHex("010300640014")));
        QCOMPARE(tx[1], withCrc16(QByteArray::fromHex("010300780014")));
        QCOMPARE(tx[2], withCrc16(QByteArray::fromHex("0103008c0014")));
    }

    void scatteredReadsFollowThePlan()
    {
        Bench b({driveConfig(1, 115200)});
        QVERIFY(b.open(115200));
        const QList<int> wanted{0, 1, 2, 19, 51, 59};
        DriveReply *r = b.drive(1)->readParameters(wanted);
        QVERIFY(waitDone(r));
        QVERIFY(r->ok());
        QCOMPARE(r->parameters().keys(), (QList<int>{0, 1, 2, 19, 51, 59}));
        QCOMPARE(b.txCount(), int(servomodbus::planReads(wanted).size()));
        QCOMPARE(b.txCount(), 2);
    }

    void writesAreBatchedAndVerified()
    {
        Bench b({driveConfig(1, 115200)});
        QVERIFY(b.open(115200));
        const QList<ParameterWrite> writes{{10, 1234}, {11, -5}, {12, 7}, {40, 99}};
        DriveReply *r = b.drive(1)->writeParameters(writes);
        QSignalSpy progress(r, &DriveReply::progress);
        QVERIFY(waitDone(r));
        QVERIFY2(r->ok(), qPrintable(r->error().message));
        QCOMPARE(b.drives[0]->parameter(10), quint16(1234));
        QCOMPARE(b.drives[0]->parameter(11), quint16(0xFFFB));
        QCOMPARE(b.drives[0]->parameter(40), quint16(99));
        QCOMPARE(r->writeResults().size(), 4);
        for (const auto &w : r->writeResults()) {
            QVERIFY(w.written);
            QVERIFY(w.verified);
            QCOMPARE(w.readBack, w.requested);
        }
        const QList<QByteArray> tx = b.txFrames();
        // Two 0x10 runs (PA10..PA12, PA40), then the read-back plan.
        QCOMPARE(tx[0], withCrc16(QByteArray::fromHex("0110006e00030604d2fffb0007")));
        QCOMPARE(tx[1],
                 withCrc16(QByteArray::fromHex("0110008c000102"
                                               "0063")));
        QCOMPARE(tx.size(), 2 + int(servomodbus::planReads({10, 11, 12, 40}).size()));
        QCOMPARE(progress.size(), tx.size());
        QCOMPARE(progress.last().at(0).toInt(), int(tx.size()));
        QCOMPARE(progress.last().at(1).toInt(), int(tx.size()));
    }

    void badValuesAreRefusedWithNothingOnTheWire()
    {
        Bench b({driveConfig(1, 115200)});
        QVERIFY(b.open(115200));
        ServoModbusDrive *d = b.drive(1);
        struct Case
        {
            QList<ParameterWrite> writes;
            ErrorCode code;
        };
        const QList<Case> cases = {
            {{{10, 70000}}, ErrorCode::OutOfRange},
            {{{10, 1}, {11, 40000}}, ErrorCode::OutOfRange}, // the dictionary: int16
            {{{51, 300}}, ErrorCode::OutOfRange},            // PA51: 0..255
            {{{2, 7060}}, ErrorCode::NotSupported},          // firmware: read-only
            {{{60, 1}}, ErrorCode::InvalidArgument},
            {{{5, 1}, {5, 2}}, ErrorCode::InvalidArgument},
        };
        for (const Case &c : cases) {
            DriveReply *r = d->writeParameters(c.writes);
            QVERIFY(waitDone(r));
            QCOMPARE(r->error().code, c.code);
        }
        DriveReply *r = d->readParameters({60});
        QVERIFY(waitDone(r));
        QCOMPARE(r->error().code, ErrorCode::InvalidArgument);
        spin(30);
        QCOMPARE(b.txCount(), 0);
        QCOMPARE(b.drives[0]->parameter(10), quint16(110));
    }

    void eeOperationsNewFormat()
    {
        Bench b({driveConfig(1, 115200, 7051)});
        QVERIFY(b.open(115200));
        SimServoModbusDrive *sim = b.drives[0];
        ServoModbusDrive *d = b.drive(1);
        sim->setParameter(20, 555);
        DriveReply *r = d->eeOperation(EeOperation::Save);
        QVERIFY(waitDone(r));
        QVERIFY2(r->ok(), qPrintable(r->error().message));
        QCOMPARE(r->info().value("eeFormat").toString(), QStringLiteral("new"));
        QCOMPARE(sim->eepromParameter(20), quint16(555));
        const QList<QByteArray> tx = b.txFrames();
        QCOMPARE(tx.last(), withCrc16(QByteArray::fromHex("0110003a0001020001")));
        // Backup, change, restore.
        QVERIFY(waitDone(r = d->eeOperation(EeOperation::Backup)) && r->ok());
        sim->setParameter(20, 1);
        QVERIFY(waitDone(r = d->eeOperation(EeOperation::RestoreBackup)) && r->ok());
        QCOMPARE(sim->parameter(20), quint16(555));
        // Reload from EEPROM, factory defaults.
        sim->setParameter(21, 9);
        QVERIFY(waitDone(r = d->eeOperation(EeOperation::Reload)) && r->ok());
        QCOMPARE(sim->parameter(21), sim->eepromParameter(21));
        QVERIFY(waitDone(r = d->eeOperation(EeOperation::FactoryDefaults)) && r->ok());
        QCOMPARE(sim->parameter(20), quint16(120));
        QCOMPARE(sim->eepromParameter(20), quint16(120));
        QCOMPARE(sim->eeOperationsCompleted(), 5);
    }

    void eeOperationsLegacyFormatArePolledUntilDone()
    {
        Bench b({driveConfig(1, 115200, 7041)});
        b.drives[0]->setEeBusyUs(200000);
        QVERIFY(b.open(115200));
        SimServoModbusDrive *sim = b.drives[0];
        sim->setParameter(30, 4321);
        QElapsedTimer t;
        t.start();
        DriveReply *r = b.drive(1)->eeOperation(EeOperation::Save);
        QVERIFY(waitDone(r));
        QVERIFY2(r->ok(), qPrintable(r->error().message));
        QVERIFY(t.elapsed() >= 200);
        QCOMPARE(r->info().value("eeFormat").toString(), QStringLiteral("legacy"));
        QVERIFY(r->info().value("polls").toInt() >= 2);
        QCOMPARE(sim->eepromParameter(30), quint16(4321));
        // PA2 was read first (auto format), then 0x06 to register 0 with op 1.
        const QList<QByteArray> tx = b.txFrames();
        QCOMPARE(tx.first(), withCrc16(QByteArray::fromHex("010300660001")));
        QCOMPARE(tx.at(1), withCrc16(QByteArray::fromHex("010600000001")));
        QVERIFY(!sim->eeRunning());
    }

    void legacyEeThatNeverFinishesTimesOutClearly()
    {
        Bench b({driveConfig(1, 115200, 7041)});
        b.drives[0]->setEeBusyUs(5000000);
        QVERIFY(b.open(115200, {{"servo-modbus.eeTimeoutMs", 300}}));
        DriveReply *r = b.drive(1)->eeOperation(EeOperation::Save);
        QVERIFY(waitDone(r));
        QCOMPARE(r->error().code, ErrorCode::Timeout);
        QVERIFY2(r->error().message.contains(QLatin1String("EE-Set")), qPrintable(r->error().message));
        QVERIFY2(r->error().message.contains(QLatin1String("still reports it running")),
                 qPrintable(r->error().message));
    }

    void eeFormatOverride()
    {
        // A legacy drive with the format forced to "new": the drive rejects it.
        Bench b({driveConfig(1, 115200, 7041)});
        b.drives[0]->setEeBusyUs(0);
        QVERIFY(b.open(115200, {{"servo-modbus.eeFormat", "new"}}));
        DriveReply *r = b.drive(1)->eeOperation(EeOperation::Save);
        QVERIFY(waitDone(r));
        QCOMPARE(r->error().code, ErrorCode::DriveException);
        QCOMPARE(r->error().driveCode, 4);
        // Forced "legacy": no PA2 read first.
        Bench l({driveConfig(1, 115200, 7041)});
        l.drives[0]->setEeBusyUs(0);
        QVERIFY(l.open(115200, {{"servo-modbus.eeFormat", "legacy"}}));
        QVERIFY(waitDone(r = l.drive(1)->eeOperation(EeOperation::Backup)));
        QVERIFY2(r->ok(), qPrintable(r->error().message));
        QCOMPARE(l.txFrames().first(), withCrc16(QByteArray::fromHex("010600000003")));
        // Bad option values are refused when opening.
        Bench bad({driveConfig(1, 115200)});
        QVERIFY(!bad.open(115200, {{"servo-modbus.eeFormat", "sometimes"}}));
    }

    void exceptionsAreReportedWithTheirCode()
    {
        // The simulated drive answers exceptions with address byte 0x01 (seed), here from 9.
        Bench b({driveConfig(9, 115200)});
        QVERIFY(b.open(115200, {}, -1, 0));
        ModbusLink *link = b.backend->link();
        LinkReply *r = link->readHoldingRegisters(9, 0x0050, 1); // between the two blocks
        QVERIFY(waitDone(r));
        QCOMPARE(r->error().code, ErrorCode::DriveException);
        QCOMPARE(r->error().driveCode, 4);
        r = link->readHoldingRegisters(9, 0x0064, 21); // more than 20 registers
        QVERIFY(waitDone(r));
        QCOMPARE(r->error().code, ErrorCode::DriveException);
        QCOMPARE(r->error().driveCode, 4);
        QCOMPARE(b.drives[0]->exceptionsSent(), quint64(2));
        // Own-address exceptions (drive option) are reported the same way.
        b.drives[0]->setExceptionAddressFixed(false);
        r = link->writeRegisters(9, 0x0000, {1, 2});
        QVERIFY(waitDone(r));
        QCOMPARE(r->error().code, ErrorCode::DriveException);
        QCOMPARE(r->error().driveCode, 4);
    }

    void channelsReadInFewRequests()
    {
        Bench b({driveConfig(1, 115200)});
        QVERIFY(b.open(115200));
        SimServoModbusDrive *sim = b.drives[0];
        ServoModbusDrive *d = b.drive(1);
        QVERIFY(sim->motor().enable());
        sim->motor().setPosition(100000);
        QVERIFY(sim->motor().runSpeed(3000.0 * 10000 / 60.0 / 3.0)); // 1000 r/min
        spin(400);
        DriveReply *r = d->readChannels({"speed", "torque", "current"});
        QVERIFY(waitDone(r));
        QVERIFY2(r->ok(), qPrintable(r->error().message));
        QCOMPARE(b.txCount(), 1);
        QVERIFY2(std::abs(r->samples().value("speed") - 1000.0) < 2.0,
                 qPrintable(QString::number(r->samples().value("speed"))));
        QVERIFY(r->samples().value("current") > 0.0);
        // Every channel: 0x00..0x16 is 23 registers, two requests.
        r = d->readChannels({});
        QVERIFY(waitDone(r));
        QVERIFY(r->ok());
        QCOMPARE(b.txCount(), 3);
        QCOMPARE(r->samples().size(), d->channels().size());
        const double pos = r->samples().value("position");
        QVERIFY(pos > 100000.0);
        QCOMPARE(r->samples().value("position-high"), std::floor(pos / 65536.0));
        QCOMPARE(r->samples().value("position-low"), pos - 65536.0 * std::floor(pos / 65536.0));
        QCOMPARE(r->samples().value("alarm"), 0.0);
        // Unknown channel: refused, nothing sent.
        r = d->readChannels({"bus-voltage"});
        QVERIFY(waitDone(r));
        QCOMPARE(r->error().code, ErrorCode::InvalidArgument);
        QCOMPARE(b.txCount(), 3);
    }

    void alarmIsReadFromDpErr()
    {
        Bench b({driveConfig(1, 115200)});
        QVERIFY(b.open(115200));
        b.drives[0]->setAlarm(12);
        ServoModbusDrive *d = b.drive(1);
        QSignalSpy alarms(d, &Drive::alarmChanged);
        DriveReply *r = d->readAlarm();
        QVERIFY(waitDone(r));
        QVERIFY(r->ok());
        QCOMPARE(r->status().alarmCode, 12);
        QCOMPARE(alarms.count(), 1);
        QCOMPARE(b.txFrames().last(), withCrc16(QByteArray::fromHex("010300130001")));
        DriveReply *c = d->clearAlarm();
        QVERIFY(waitDone(c));
        QCOMPARE(c->error().code, ErrorCode::NotSupported);
        QVERIFY(!d->unsupportedReason(Capability::ClearAlarm).isEmpty());
        QVERIFY(!d->hasCapability(Capability::Jog));
        DriveReply *j = d->jog(100);
        QVERIFY(waitDone(j));
        QCOMPARE(j->error().code, ErrorCode::NotSupported);
    }

    void lateReplyIsNeverTakenForTheNextRequest()
    {
        Bench b({driveConfig(1, 115200)});
        QVERIFY(b.open(115200, {}, 30, 0));
        SimServoModbusDrive *sim = b.drives[0];
        ServoModbusDrive *d = b.drive(1);
        sim->setParameter(5, 1111);
        sim->faults().setExtraLatency(60); // answers after the 30 ms allowance
        DriveReply *first = d->readParameters({5});
        QVERIFY(waitDone(first));
        QCOMPARE(first->error().code, ErrorCode::Timeout);
        sim->faults().setExtraLatency(0);
        sim->setParameter(5, 2222);
        DriveReply *second = d->readParameters({5});
        QVERIFY(waitDone(second));
        QVERIFY2(second->ok(), qPrintable(second->error().message));
        QCOMPARE(second->parameters().value(5), qint64(2222));
    }

    void dropsAndCorruptionAreRecovered()
    {
        Bench b({driveConfig(1, 115200)});
        QVERIFY(b.open(115200, {}, 20, 6));
        SimServoModbusDrive *sim = b.drives[0];
        FaultSettings f;
        f.dropRate = 0.2;
        f.corruptRate = 0.2;
        f.seed = 11;
        sim->faults().setSettings(f);
        for (int round = 0; round < 5; ++round) {
            DriveReply *r = b.drive(1)->readParameters(allParameters());
            QVERIFY(waitDone(r));
            QVERIFY2(r->ok(), qPrintable(r->error().message));
            for (int n = 0; n < 60; ++n)
                QCOMPARE(r->parameters().value(n), qint64(qint16(sim->parameter(n))));
        }
        QVERIFY(b.backend->link()->retryCount() > 0);
    }

    void scanFindsDrivesAtUnknownAddressesAndBauds()
    {
        Bench b({driveConfig(7, 19200, 7051), driveConfig(23, 9600, 7041)});
        QVERIFY(b.open(38400));
        ScanOptions o;
        o.from = 1;
        o.to = 30;
        o.bauds = {9600, 19200, 38400};
        Discovery *scan = b.backend->createDiscovery(o);
        QSignalSpy finished(scan, &Discovery::finished);
        QSignalSpy progress(scan, &Discovery::progress);
        scan->start();
        QVERIFY(finished.wait(30000));
        QVERIFY2(!finished.at(0).at(0).value<Error>().isError(),
                 qPrintable(finished.at(0).at(0).value<Error>().message));
        QCOMPARE(scan->results().size(), 2);
        QCOMPARE(scan->results()[0].address, 23);
        QCOMPARE(scan->results()[0].baud, 9600);
        QCOMPARE(scan->results()[0].firmware, QStringLiteral("7041"));
        QCOMPARE(scan->results()[1].address, 7);
        QCOMPARE(scan->results()[1].baud, 19200);
        QCOMPARE(scan->results()[1].firmware, QStringLiteral("7051"));
        QCOMPARE(progress.last().at(0).toInt(), 90);
        QCOMPARE(progress.last().at(1).toInt(), 90);
        QCOMPARE(b.backend->link()->settings().baud, 38400); // restored
    }

    void scanAsksADriveAgainWhoseReplyCameLate()
    {
        Bench b({driveConfig(5, 115200, 7051)});
        QVERIFY(b.open(115200));
        // Drive 5 answers 20 ms late: after its probe's timeout (no first byte by the end of
        // the request + 4 ms), so only its late reply shows that it is there. It is the last address
        // of the sweep, so its reply lands in the wait after the last probe (2 x the probe
        // timeout, at least 50 ms) and not on top of a later probe (the simulated bus garbles
        // colliding frames, as a real one does): margins of 10 ms and 40 ms, so that a busy
        // machine does not move the reply into the timeout or past the wait.
        b.drives[0]->faults().setExtraLatency(20);
        ScanOptions o;
        o.from = 1;
        o.to = 5;
        auto *scan = qobject_cast<ServoModbusScanner *>(b.backend->createDiscovery(o));
        QVERIFY(scan);
        QVERIFY(scan->probeTimeoutMs() < 15);
        QSignalSpy finished(scan, &Discovery::finished);
        QSignalSpy progress(scan, &Discovery::progress);
        scan->start();
        QVERIFY(finished.wait(10000));
        QVERIFY(!finished.at(0).at(0).value<Error>().isError());
        QList<int> found;
        for (const DiscoveredDrive &d : scan->results())
            found << d.address;
        QCOMPARE(found, (QList<int>{5}));
        QCOMPARE(scan->probesSent(), 6); // 5 addresses + drive 5 once more
        QCOMPARE(progress.last().at(0).toInt(), 5);
    }

    void scanWaitsForTheLastDriveAsLongAsALateOneTook()
    {
        Bench b({driveConfig(1, 115200, 7051), driveConfig(2, 115200, 7052), driveConfig(6, 115200, 7053)});
        QVERIFY(b.open(115200, {}, 200)); // the normal timeout (of the second asking): 200 ms
        // Probes of 40 ms (an explicit timeout is the whole timeout; the sweep's usual final wait is
        // 2 x 40 = 80 ms). Drive 1 answers at once; drive 2 answers 60 ms after its probe, in
        // the middle of the next probe's wait, and is asked again; drive 6, the last
        // address, answers 140 ms after its probe: 20 ms after the usual final wait ended.
        // The scanner waits twice as long as drive 2's reply took (> 120 ms) instead.
        b.drives[1]->faults().setExtraLatency(60);
        b.drives[2]->faults().setExtraLatency(140);
        ScanOptions o;
        o.from = 1;
        o.to = 6;
        o.timeoutMs = 40;
        auto *scan = qobject_cast<ServoModbusScanner *>(b.backend->createDiscovery(o));
        QVERIFY(scan);
        QCOMPARE(scan->finalWaitMs(), 80); // nothing learned yet: 2 probe timeouts
        QSignalSpy finished(scan, &Discovery::finished);
        scan->start();
        QVERIFY(finished.wait(10000));
        QVERIFY(!finished.at(0).at(0).value<Error>().isError());
        QList<int> found;
        for (const DiscoveredDrive &d : scan->results())
            found << d.address;
        std::sort(found.begin(), found.end());
        QCOMPARE(found, (QList<int>{1, 2, 6}));
        QVERIFY(scan->finalWaitMs() > 120); // twice drive 2's lateness
        QCOMPARE(scan->probesSent(), 8);    // 6 addresses + drives 2 and 6 once more
    }

    // The link reports a late reply's bytes (stray) before it reports the timeout of the
    // probe they answer: the scanner must still ask that address again.
    void scanAsksAgainWhenTheLateReplyCameBeforeTheTimeout()
    {
        Bench b({});
        QVERIFY(b.open(115200));
        ScanOptions o;
        o.from = 1;
        o.to = 3;
        auto *scan = qobject_cast<ServoModbusScanner *>(b.backend->createDiscovery(o));
        QVERIFY(scan);
        ModbusLink *link = b.backend->link();
        const QByteArray late = withCrc16(QByteArray::fromHex("0203021B8B"));
        // While the probe of address 2 waits (its request was recorded), the link reports
        // an answer from address 2 as stray: what it does when the answer misses the wait.
        bool sent = false;
        connect(&b.tap, &TrafficTap::frameRecorded, this, [&](const TrafficRecord &r) {
            if (!sent && r.direction == TrafficRecord::Direction::Tx && quint8(r.bytes.at(0)) == 2) {
                sent = true;
                QMetaObject::invokeMethod(
                    link, [link, late] { emit link->strayBytes(late); }, Qt::QueuedConnection);
            }
        });
        QSignalSpy finished(scan, &Discovery::finished);
        scan->start();
        QVERIFY(finished.wait(10000));
        QVERIFY(sent);
        QVERIFY(scan->results().isEmpty()); // nobody is there when asked again
        QCOMPARE(scan->probesSent(), 4);    // 3 addresses + address 2 once more
    }

    void scanCanBeCancelled()
    {
        Bench b({driveConfig(7, 9600)});
        QVERIFY(b.open(9600));
        ScanOptions o;
        o.bauds = {9600};
        Discovery *scan = b.backend->createDiscovery(o);
        QSignalSpy finished(scan, &Discovery::finished);
        scan->start();
        spin(100);
        scan->cancel();
        QVERIFY(finished.wait(2000));
        QCOMPARE(finished.at(0).at(0).value<Error>().code, ErrorCode::Cancelled);
        DriveReply *r = b.drive(7)->readParameters({1});
        QVERIFY(waitDone(r));
        QVERIFY2(r->ok(), qPrintable(r->error().message));
    }

    void lostAdapterIsReported()
    {
        Bench b({driveConfig(1, 115200)});
        QVERIFY(b.open(115200));
        QSignalSpy lost(b.backend.get(), &FamilyBackend::linkLost);
        QSignalSpy driveLost(b.drive(1), &Drive::connectionLost);
        b.pty->close();
        QVERIFY(lost.wait(2000) || lost.count() == 1);
        QCOMPARE(lost.at(0).at(0).value<Error>().code, ErrorCode::LinkClosed);
        QCOMPARE(driveLost.count(), 1);
    }
};

QTEST_GUILESS_MAIN(TestServoModbusDrive)
#include "tst_servomodbusdrive.moc"
