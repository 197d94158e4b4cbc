// Frames from a misbehaving servo-can drive: a SimServoCanDrive whose read replies (0x12) a
// wrapper rewrites — another station, another read type, another parameter index, a short
// frame, an extended ID, a remote-less empty frame, a frame of another command — answers the
// real host stack (ServoCanBackend over a private VirtualCanHub). None of these answers the
// request, so each read must end in Timeout (after the retries) with a specific message, and
// no value may be reported. Heartbeats stay untouched, so the station stays online.
#include <QtTest>

#include "core/drive/servocan/servocanbackend.h"
#include "core/drive/servocan/servocandrive.h"
#include "core/drive/servocan/servocanstationtracker.h"
#include "core/protocol/servocan/servocan.h"
#include "sim/bus/simcanbus.h"
#include "sim/bus/virtualcanhub.h"
#include "sim/servocan/simservocandrive.h"
#include "tests/integration/faultcheck.h"
#include "tests/support/simcanconnect.h"

#include <memory>

using namespace dd;
using namespace dd::faultcheck;
namespace sc = dd::servocan;

namespace {

enum class CanMisbehaviour { None, OtherStation, OtherType, OtherIndex, Short, Extended, Empty, OtherCommand };

class MisbehavingCanDrive : public SimCanDevice
{
public:
    explicit MisbehavingCanDrive(int station)
        : m_drive(station)
    {
    }
    CanMisbehaviour mode = CanMisbehaviour::None;
    quint64 rewritten = 0;
    SimServoCanDrive &drive() { return m_drive; }

    QList<CanFrameData> onCanFrame(const CanFrameData &frame, qint64 nowUs) override
    {
        QList<CanFrameData> out;
        for (CanFrameData f : m_drive.onCanFrame(frame, nowUs)) {
            if (mode != CanMisbehaviour::None && f.data.size() == 8 && quint8(f.data.at(1)) == 0x12) {
                ++rewritten;
                rewrite(f);
            }
            out.append(f);
        }
        return out;
    }
    QList<CanFrameData> tick(qint64 nowUs) override { return m_drive.tick(nowUs); }
    QString describe() const override { return QStringLiteral("misbehaving ") + m_drive.describe(); }
    void advanceTo(qint64 nowUs) override { m_drive.advanceTo(nowUs); }

private:
    void rewrite(CanFrameData &f) const
    {
        switch (mode) {
        case CanMisbehaviour::None: break;
        case CanMisbehaviour::OtherStation: // a second drive with the same ID, another station byte
            f.data[0] = char(quint8(f.data.at(0)) + 1);
            break;
        case CanMisbehaviour::OtherType: f.data[2] = char(0xFE); break;
        case CanMisbehaviour::OtherIndex: f.data[3] = char(quint8(f.data.at(3)) ^ 0x80); break;
        case CanMisbehaviour::Short: f.data.chop(1); break;
        case CanMisbehaviour::Extended: f.extended = true; break;
        case CanMisbehaviour::Empty: f.data.clear(); break;
        case CanMisbehaviour::OtherCommand: f.data[1] = char(0x15); break;
        }
    }
    SimServoCanDrive m_drive;
};

} // namespace

Q_DECLARE_METATYPE(CanMisbehaviour)

class TestFaultFramesCan : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void badReplies_data();
    void badReplies();

private:
    std::unique_ptr<VirtualCanHub> m_hub;
    std::unique_ptr<SimCanBus> m_bus;
    MisbehavingCanDrive *m_dev = nullptr;
    std::unique_ptr<ServoCanBackend> m_backend;
};

void TestFaultFramesCan::initTestCase()
{
    m_hub = std::make_unique<VirtualCanHub>();
    QVERIFY(m_hub->start());
    m_bus = std::make_unique<SimCanBus>();
    m_dev = static_cast<MisbehavingCanDrive *>(m_bus->addDevice(std::make_unique<MisbehavingCanDrive>(3)));
    const QString busError = test::connectSimCanBus(m_bus.get(), m_hub->interfaceName(0));
    QVERIFY2(busError.isEmpty(), qPrintable(busError));
    ConnectionSettings cs;
    cs.family = Family::ServoCan;
    cs.can = QStringLiteral("virtualcan:") + m_hub->interfaceName(0);
    m_backend = std::make_unique<ServoCanBackend>();
    Error oe;
    QVERIFY2(m_backend->open(cs, nullptr, &oe), qPrintable(oe.message));
    QVERIFY(waitUntil([this] { return m_backend->tracker()->isOnline(3); }, 3000));
}

void TestFaultFramesCan::cleanupTestCase()
{
    m_backend.reset();
    m_bus.reset();
    m_hub.reset();
}

void TestFaultFramesCan::badReplies_data()
{
    QTest::addColumn<CanMisbehaviour>("mode");
    QTest::newRow("other station") << CanMisbehaviour::OtherStation;
    QTest::newRow("other read type") << CanMisbehaviour::OtherType;
    QTest::newRow("other index") << CanMisbehaviour::OtherIndex;
    QTest::newRow("7 bytes") << CanMisbehaviour::Short;
    QTest::newRow("extended id") << CanMisbehaviour::Extended;
    QTest::newRow("no data") << CanMisbehaviour::Empty;
    QTest::newRow("other command") << CanMisbehaviour::OtherCommand;
}

void TestFaultFramesCan::badReplies()
{
    QFETCH(CanMisbehaviour, mode);
    ServoCanDrive *d = m_backend->servoDrive(3);
    const auto before = m_dev->drive().parameters();
    m_dev->mode = mode;
    m_dev->rewritten = 0;
    DriveReply *r = d->readParameters({10, 11, 12});
    QVERIFY2(waitFinished(r, 3000), "a bad answer must not hang the read");
    QCOMPARE(errorCodeName(r->error().code), errorCodeName(ErrorCode::Timeout));
    QVERIFY2(r->error().message.contains(QStringLiteral("Station 3, P1")), qPrintable(r->error().message));
    QVERIFY2(r->error().message.contains(QStringLiteral("3 attempts")), qPrintable(r->error().message));
    QVERIFY(r->parameters().isEmpty());
    QCOMPARE(m_dev->rewritten, quint64(9)); // three reads, three attempts each
    QVERIFY(m_dev->drive().parameters() == before);
    // A write is read back the same way: not verified, and the reason says so.
    DriveReply *w = d->writeParameters({{20, 123}});
    QVERIFY(waitFinished(w, 3000));
    QVERIFY(w->error().isError());
    QCOMPARE(w->writeResults().size(), 1);
    QVERIFY(!w->writeResults().first().verified);
    QVERIFY2(w->writeResults().first().error.contains(QStringLiteral("could not be read back")),
             qPrintable(w->writeResults().first().error));
    // Unknown, not a mismatch: the batch keeps the read-back's own error (it was
    // VerifyMismatch before WriteVerification) and names the parameter.
    QCOMPARE(w->writeResults().first().outcome, WriteOutcome::Unknown);
    QCOMPARE(errorCodeName(w->error().code), errorCodeName(ErrorCode::Timeout));
    QVERIFY2(w->error().message.startsWith(QStringLiteral("P20: ")), qPrintable(w->error().message));
    // Recovery.
    m_dev->mode = CanMisbehaviour::None;
    r = d->readParameters({10, 11, 12});
    QVERIFY(waitFinished(r, 3000));
    QVERIFY2(r->ok(), qPrintable(r->error().message));
    for (int p = 10; p <= 12; ++p)
        QCOMPARE(r->parameters().value(p), qint64(m_dev->drive().parameter(p)));
    QVERIFY(m_backend->tracker()->isOnline(3));
}

QTEST_GUILESS_MAIN(TestFaultFramesCan)
#include "tst_faultframescan.moc"
