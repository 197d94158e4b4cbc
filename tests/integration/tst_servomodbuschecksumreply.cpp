// The servo-modbus seed's error reply after line noise (docs/protocols/servo-modbus.md,
// "Exceptions"): a drive that finds a request to its address damaged (bad CRC) answers
// [0x01][function | 0x80][0x04] — the address byte is fixed 0x01 whatever the drive's
// address. What the host makes of it, end to end (ServoModbusBackend over a pty against
// SimServoModbusDrive on a SimSerialBus, whose test hook damages requests on their way):
//  - a read that drew it is asked again and returns the value (exception 0x04 also means
//    "your request arrived damaged"; it takes one of the request's retries);
//  - a scan probe that drew it finds the probed drive, with its firmware, and no drive 1;
//  - such a reply that comes late (after the request timed out) is not taken for the answer
//    of drive 1 asked next.
#include "core/drive/servomodbus/servomodbusbackend.h"
#include "core/drive/servomodbus/servomodbusdrive.h"
#include "core/drive/servomodbus/servomodbusscanner.h"
#include "core/link/traffictap.h"
#include "sim/bus/ptyendpoint.h"
#include "sim/bus/simserialbus.h"
#include "sim/servomodbus/simservomodbusdrive.h"
#include "tests/support/replywait.h"

#include <QSignalSpy>
#include <QtTest>

#include <memory>

using namespace dd;

namespace {

struct ChecksumBench
{
    SimSerialBus *bus = nullptr;
    PtyEndpoint *pty = nullptr;
    QList<SimServoModbusDrive *> drives;
    TrafficTap tap;
    std::unique_ptr<ServoModbusBackend> backend;

    explicit ChecksumBench(const QList<int> &addresses)
    {
        pty = new PtyEndpoint;
        if (pty->open().isError())
            return;
        bus = new SimSerialBus(pty);
        for (int a : addresses) {
            SimServoModbusDrive::Config c;
            c.address = a;
            c.baud = 115200;
            c.firmware = quint16(7050 + a);
            drives << static_cast<SimServoModbusDrive *>(bus->addDevice(std::make_unique<SimServoModbusDrive>(c)));
        }
    }
    ~ChecksumBench()
    {
        backend.reset();
        delete bus;
    }
    bool open(int timeoutMs = -1, int retries = -1)
    {
        ConnectionSettings cs;
        cs.family = Family::ServoModbus;
        cs.port = pty->clientPath();
        cs.baud = 115200;
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
};

// PA5 of a drive as read through the backend; nullopt with the error in `error`.
std::optional<qint64> readPa5(ServoModbusDrive *d, Error *error)
{
    DriveReply *r = d->readParameters({5});
    if (!test::waitInEventLoop(r, 10000)) {
        *error = {ErrorCode::Timeout, QStringLiteral("no answer from the test")};
        return std::nullopt;
    }
    r->deleteLater();
    *error = r->error();
    if (!r->ok())
        return std::nullopt;
    return r->parameters().value(5);
}

} // namespace

class TestServoModbusChecksumReply : public QObject
{
    Q_OBJECT

private slots:
    void damagedReadIsAskedAgain()
    {
        ChecksumBench b({5});
        QVERIFY(b.open());
        b.drives[0]->damageIncomingRequests(1);
        Error e;
        const std::optional<qint64> v = readPa5(b.drive(5), &e);
        QVERIFY2(v, qPrintable(e.message));
        QCOMPARE(*v, qint64(qint16(b.drives[0]->parameter(5))));
        QCOMPARE(b.drives[0]->checksumErrors(), quint64(1));
        QCOMPARE(b.drives[0]->exceptionsSent(), quint64(1));
    }

    void damagedReadWithoutRetriesReportsTheException()
    {
        ChecksumBench b({5});
        QVERIFY(b.open(-1, 0));
        b.drives[0]->damageIncomingRequests(1);
        Error e;
        QVERIFY(!readPa5(b.drive(5), &e));
        QCOMPARE(e.code, ErrorCode::DriveException);
        QCOMPARE(e.driveCode, 4);
        // The next request is answered normally.
        QVERIFY(readPa5(b.drive(5), &e));
    }

    void damagedProbeFindsTheProbedDrive()
    {
        ChecksumBench b({5});
        QVERIFY(b.open());
        b.drives[0]->damageIncomingRequests(1);
        ScanOptions o;
        o.from = 1;
        o.to = 6;
        Discovery *scan = b.backend->createDiscovery(o);
        QSignalSpy finished(scan, &Discovery::finished);
        scan->start();
        QVERIFY(finished.wait(10000));
        QVERIFY(!finished.at(0).at(0).value<Error>().isError());
        QCOMPARE(scan->results().size(), 1);
        QCOMPARE(scan->results()[0].address, 5);
        QCOMPARE(scan->results()[0].firmware, QStringLiteral("7055"));
        QCOMPARE(b.drives[0]->checksumErrors(), quint64(1));
    }

    void lateErrorReplyIsNotDriveOnesAnswer()
    {
        ChecksumBench b({1, 5});
        QVERIFY(b.open(30, 0));
        // Drive 5's reply comes 60 ms late: after the 30 ms the host waits.
        b.drives[0]->setParameter(5, 4321);
        b.drives[1]->faults().setExtraLatency(60);
        b.drives[1]->damageIncomingRequests(1);
        Error e;
        QVERIFY(!readPa5(b.drive(5), &e));
        QCOMPARE(e.code, ErrorCode::Timeout);
        // Drive 1 is asked while drive 5's "01 83 04" is on its way.
        b.drives[1]->faults().setExtraLatency(0);
        const std::optional<qint64> v = readPa5(b.drive(1), &e);
        QVERIFY2(v, qPrintable(e.message));
        QCOMPARE(*v, qint64(4321));
        QCOMPARE(b.drives[1]->exceptionsSent(), quint64(1));
        QCOMPARE(b.drives[0]->exceptionsSent(), quint64(0));
    }
};

QTEST_GUILESS_MAIN(TestServoModbusChecksumReply)
#include "tst_servomodbuschecksumreply.moc"
