// Frames from a misbehaving drive. A scripted servo-modbus drive on a pty (a real
// SimServoModbusDrive whose replies a wrapper rewrites: wrong address, wrong function code,
// truncated, wrong byte count, garbage, bad CRC, an exception, a duplicated reply) answers
// the real host stack (ServoModbusBackend: ModbusLink on SerialLink). Each
// misbehaviour must give a specific error, no value may be reported, and nothing may be
// written to the drive. Writes whose reply is damaged are judged by their read-back: the
// report never says "not written" for a value the drive holds, nor "verified" for one it
// does not.
#include <QtTest>

#include "core/drive/servomodbus/servomodbusbackend.h"
#include "core/drive/servomodbus/servomodbusdrive.h"
#include "core/link/modbuslink.h"
#include "core/protocol/modbus/crc16.h"
#include "sim/bus/ptyendpoint.h"
#include "sim/bus/simserialbus.h"
#include "sim/servomodbus/simservomodbusdrive.h"
#include "tests/support/requiretool.h"

#include <memory>

using namespace dd;

namespace {

enum class Misbehaviour {
    None,
    WrongAddress,   // a well-formed reply from another address
    WrongFunction,  // a well-formed reply with function 0x04
    Truncated,      // the last three bytes never come
    ShortByteCount, // well-formed, CRC right, but two registers fewer than asked for
    LongByteCount,  // well-formed, CRC right, one register more than asked for
    Garbage,        // noise of a reply's length
    BadCrc,         // one bit of the CRC flipped
    Exception,      // exception 0x02 (illegal data address) from the drive's own address
    Duplicate,      // every reply is sent twice, the copy right behind it
    WrongEcho,      // a 0x10 reply echoes another register count
};

QByteArray recrc(QByteArray adu)
{
    adu.chop(2);
    return withCrc16(adu);
}

// The drive's real answers, rewritten according to `mode` (for reads only, or writes only).
class MisbehavingDrive : public SimSerialDevice
{
public:
    explicit MisbehavingDrive(const SimServoModbusDrive::Config &c)
        : m_drive(c)
    {
    }

    Misbehaviour mode = Misbehaviour::None;
    quint64 rewritten = 0;

    SimServoModbusDrive &drive() { return m_drive; }

    QList<QByteArray> onBusBytes(const QByteArray &bytes, qint64 nowUs) override
    {
        QList<QByteArray> out;
        for (const QByteArray &reply : m_drive.onBusBytes(bytes, nowUs))
            out += rewrite(reply);
        return out;
    }
    int baud() const override { return m_drive.baud(); }
    QString describe() const override { return QStringLiteral("misbehaving ") + m_drive.describe(); }
    void advanceTo(qint64 nowUs) override { m_drive.advanceTo(nowUs); }

private:
    QList<QByteArray> rewrite(QByteArray a)
    {
        const quint8 fc = quint8(a.at(1));
        const bool write = fc == 0x10;
        if (mode == Misbehaviour::None || (mode == Misbehaviour::WrongEcho) != write)
            return {a};
        ++rewritten;
        switch (mode) {
        case Misbehaviour::None: break;
        case Misbehaviour::WrongAddress: a[0] = char(quint8(a.at(0)) + 4); return {recrc(a)};
        case Misbehaviour::WrongFunction: a[1] = char(0x04); return {recrc(a)};
        case Misbehaviour::Truncated: a.chop(3); return {a};
        case Misbehaviour::ShortByteCount:
            a[2] = char(quint8(a.at(2)) - 4);
            a.remove(3, 4);
            return {recrc(a)};
        case Misbehaviour::LongByteCount:
            a[2] = char(quint8(a.at(2)) + 2);
            a.insert(a.size() - 2, QByteArray::fromHex("1234"));
            return {recrc(a)};
        case Misbehaviour::Garbage: {
            QByteArray g(a.size(), '\0');
            for (int i = 0; i < g.size(); ++i)
                g[i] = char(0xA5 ^ (i * 37));
            return {g};
        }
        case Misbehaviour::BadCrc: a[a.size() - 1] = char(a.at(a.size() - 1) ^ 0x10); return {a};
        case Misbehaviour::Exception: return {withCrc16(QByteArray::fromHex("0183") + QByteArray(1, char(0x02)))};
        case Misbehaviour::Duplicate:
            // One transmission, as on a wire: the copy follows the reply with no gap. (As two
            // writes, a stall of this machine could hold the copy back until after the next
            // request, where nothing could tell it from that request's answer: a timing the
            // wire never has. docs/reliability.md, "What the rule cannot tell apart".)
            return {a + a};
        case Misbehaviour::WrongEcho:
            a[5] = char(quint8(a.at(5)) + 1); // the count's low byte
            return {recrc(a)};
        }
        return {a};
    }

    SimServoModbusDrive m_drive;
};

template <typename R>
bool waitDone(R *r, int ms = 10000)
{
    if (r->isFinished())
        return true;
    QSignalSpy spy(r, &R::finished);
    return spy.wait(ms);
}

} // namespace

Q_DECLARE_METATYPE(Misbehaviour)

class TestFaultFrames : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();
    void badReplyToARead_data();
    void badReplyToARead();
    void duplicatedRepliesAreNeverTakenForTheNextAnswer();
    void damagedWriteEchoIsJudgedByTheReadBack();
    void refusedReadBackLeavesTheWriteUnconfirmed();

private:
    ServoModbusDrive *drive() { return static_cast<ServoModbusDrive *>(m_backend->drive(1)); }
    SimServoModbusDrive &sim() { return m_dev->drive(); }

    PtyEndpoint *m_pty = nullptr;
    std::unique_ptr<SimSerialBus> m_bus;
    MisbehavingDrive *m_dev = nullptr;
    std::unique_ptr<ServoModbusBackend> m_backend;
    SimServoModbusDrive::ParameterArray m_before{};
};

void TestFaultFrames::initTestCase()
{
    DD_REQUIRE_TOOL(PtyEndpoint::isSupported(), "no pseudo-terminals on this platform");
    m_pty = new PtyEndpoint;
    const Error pe = m_pty->open();
    QVERIFY2(!pe.isError(), qPrintable(pe.message));
    m_bus = std::make_unique<SimSerialBus>(m_pty);
    SimServoModbusDrive::Config c;
    c.address = 1;
    c.baud = 115200;
    m_dev = static_cast<MisbehavingDrive *>(m_bus->addDevice(std::make_unique<MisbehavingDrive>(c)));
    ConnectionSettings cs;
    cs.family = Family::ServoModbus;
    cs.port = m_pty->clientPath();
    cs.baud = 115200;
    cs.timeoutMs = 40;
    cs.retries = 1;
    m_backend = std::make_unique<ServoModbusBackend>();
    Error e;
    QVERIFY2(m_backend->open(cs, nullptr, &e), qPrintable(e.message));
}

void TestFaultFrames::cleanupTestCase()
{
    m_backend.reset();
    m_bus.reset();
}

void TestFaultFrames::init()
{
    m_dev->mode = Misbehaviour::None;
    m_dev->rewritten = 0;
    m_before = sim().parameters();
}

void TestFaultFrames::badReplyToARead_data()
{
    QTest::addColumn<Misbehaviour>("mode");
    QTest::addColumn<ErrorCode>("code");
    QTest::addColumn<QString>("fragment");
    QTest::newRow("wrong address") << Misbehaviour::WrongAddress << ErrorCode::Timeout << "from address 5";
    QTest::newRow("wrong function") << Misbehaviour::WrongFunction << ErrorCode::Timeout << "function";
    QTest::newRow("truncated") << Misbehaviour::Truncated << ErrorCode::Timeout << "incomplete";
    QTest::newRow("short byte count") << Misbehaviour::ShortByteCount << ErrorCode::Malformed << "does not fit";
    QTest::newRow("long byte count") << Misbehaviour::LongByteCount << ErrorCode::Malformed << "does not fit";
    QTest::newRow("garbage") << Misbehaviour::Garbage << ErrorCode::ChecksumError << "CRC";
    QTest::newRow("bad crc") << Misbehaviour::BadCrc << ErrorCode::ChecksumError << "CRC";
    QTest::newRow("exception") << Misbehaviour::Exception << ErrorCode::DriveException << "0x02";
}

void TestFaultFrames::badReplyToARead()
{
    QFETCH(Misbehaviour, mode);
    QFETCH(ErrorCode, code);
    QFETCH(QString, fragment);
    m_dev->mode = mode;
    DriveReply *r = drive()->readParameters({5, 6, 7, 8, 9});
    QVERIFY(waitDone(r));
    QVERIFY(m_dev->rewritten > 0);
    qInfo().noquote() << errorCodeName(r->error().code) << r->error().message;
    QCOMPARE(errorCodeName(r->error().code), errorCodeName(code));
    QVERIFY2(r->error().message.contains(fragment, Qt::CaseInsensitive), qPrintable(r->error().message));
    QVERIFY(r->parameters().isEmpty());
    QVERIFY(sim().parameters() == m_before);
    // The link is fine afterwards.
    m_dev->mode = Misbehaviour::None;
    r = drive()->readParameters({5, 6, 7, 8, 9});
    QVERIFY(waitDone(r));
    QVERIFY2(r->ok(), qPrintable(r->error().message));
    for (int n = 5; n <= 9; ++n)
        QCOMPARE(r->parameters().value(n), qint64(qint16(sim().parameter(n))));
}

void TestFaultFrames::duplicatedRepliesAreNeverTakenForTheNextAnswer()
{
    m_dev->mode = Misbehaviour::Duplicate;
    for (int n = 10; n < 20; ++n)
        sim().setParameter(n, quint16(1000 + n));
    m_before = sim().parameters();
    // Each read has the same length, address and function as the next one: a stale second
    // copy would fit it, were it taken for the next request's answer.
    int ok = 0;
    for (int round = 0; round < 3; ++round) {
        for (int n = 10; n < 20; ++n) {
            DriveReply *r = drive()->readParameters({n});
            QVERIFY(waitDone(r));
            if (r->ok()) {
                ++ok;
                QCOMPARE(r->parameters().value(n), qint64(1000 + n));
            } else {
                QVERIFY2(r->parameters().isEmpty(), qPrintable(r->error().message));
            }
        }
    }
    qInfo("duplicated replies: %d of 30 reads answered, %llu stale answers discarded", ok,
          static_cast<unsigned long long>(m_backend->link()->lateReplyCount()));
    QVERIFY(m_dev->rewritten >= 30);
    QVERIFY(sim().parameters() == m_before);
}

void TestFaultFrames::damagedWriteEchoIsJudgedByTheReadBack()
{
    m_dev->mode = Misbehaviour::WrongEcho;
    const qint64 old = qint16(sim().parameter(12));
    DriveReply *r = drive()->writeParameters({{12, old + 7}, {30, 0}});
    QVERIFY(waitDone(r));
    QVERIFY(m_dev->rewritten > 0);
    QCOMPARE(sim().parameter(12), quint16(old + 7)); // the drive took the value ...
    QCOMPARE(r->writeResults().size(), 2);
    for (const ParameterWriteResult &w : r->writeResults()) {
        // ... and the report says so: verified by the read-back, which is what counts.
        QVERIFY2(w.written && w.verified, qPrintable(w.error));
        QCOMPARE(w.readBack, w.requested);
    }
    QVERIFY2(r->ok(), qPrintable(r->error().message));
}

void TestFaultFrames::refusedReadBackLeavesTheWriteUnconfirmed()
{
    // The write is answered properly, the read-back with an exception: written, not verified.
    m_dev->mode = Misbehaviour::Exception;
    const qint64 old = qint16(sim().parameter(20));
    DriveReply *r = drive()->writeParameters({{20, old + 3}});
    QVERIFY(waitDone(r));
    QCOMPARE(sim().parameter(20), quint16(old + 3));
    QCOMPARE(r->writeResults().size(), 1);
    const ParameterWriteResult &w = r->writeResults().first();
    QVERIFY(w.written);
    QVERIFY(!w.verified);
    QVERIFY(!w.error.isEmpty());
    QVERIFY(w.readBackFailed);
    QCOMPARE(w.outcome, WriteOutcome::ReadBackFailed);
    QCOMPARE(r->error().code, ErrorCode::DriveException);
    // The batch's error names the parameter (before WriteVerification: the bare read error).
    QVERIFY2(r->error().message.startsWith(QStringLiteral("PA20: Written, but it could not be read back: ")),
             qPrintable(r->error().message));
}

QTEST_GUILESS_MAIN(TestFaultFrames)
#include "tst_faultframes.moc"
