// The shuoke family end to end over CAN: the real ShuokeBackend on a CanLink (virtualcan,
// private port) against simulated Shuoke drives on a SimCanBus.
#include <QtTest>

#include "core/drive/driveconnection.h"
#include "core/drive/drivereply.h"
#include "core/drive/shuoke/shuokebackend.h"
#include "core/drive/shuoke/shuokecantransport.h"
#include "core/drive/shuoke/shuokedrive.h"
#include "sim/bus/simcanbus.h"
#include "tests/support/driveprobe.h"
#include "tests/support/shuokecanbench.h"
#include "tests/support/shuokeserialbench.h"
#include "tests/support/waitok.h"

#include <cmath>
#include <memory>

using namespace dd;
using namespace dd::shuoke;

class TestShuokeCanLink : public QObject
{
    Q_OBJECT

    std::unique_ptr<ShuokeCanBench> m_bench;
    SimShuokeCanDevice *m_sim = nullptr;
    ShuokeDrive *m_drive = nullptr;

    static SimShuokeDrive::Config config(Model model = Model::M6505, quint8 address = 1)
    {
        SimShuokeDrive::Config c;
        c.model = model;
        c.address = address;
        return c;
    }

    bool setUp(const QList<SimShuokeDrive::Config> &drives, const QVariantMap &options = {})
    {
        ConnectionSettings s;
        s.options = options;
        m_bench = ShuokeCanBench::create(drives, s);
        if (!m_bench)
            return false;
        if (!m_sim)
            m_sim = m_bench->devices().first();
        m_drive = m_bench->drive(drives.first().address);
        m_drive->setJogLeaseMs(60000);
        return true;
    }

    double channel(const QString &id, ShuokeDrive *drive = nullptr)
    {
        return test::readChannel(drive ? drive : m_drive, id);
    }

    bool running() { return test::readRunning(m_drive); }

private slots:
    void cleanup()
    {
        m_bench.reset();
        m_sim = nullptr;
        m_drive = nullptr;
    }

    void defaults()
    {
        QVERIFY(setUp({config()}));
        auto *can = qobject_cast<ShuokeCanTransport *>(m_bench->backend()->transport());
        QVERIFY(can);
        QCOMPARE(can->bitrate(), 100000); // bitrate code 12
        QCOMPARE(canBitrateForCode(kDefaultCanBitrateCode), can->bitrate());
        QVERIFY(!m_bench->backend()->drive(251));
        QVERIFY(m_bench->backend()->drive(250));
    }

    void parametersTwoDrives()
    {
        QVERIFY(setUp({config(Model::M6505, 1), config(Model::M4505S, 7)}));
        ShuokeDrive *other = m_bench->drive(7);
        WAIT_OK(m_drive->refreshIdentity());
        WAIT_OK(other->refreshIdentity());
        QCOMPARE(m_drive->identity().model, QStringLiteral("M6505"));
        QCOMPARE(other->identity().model, QStringLiteral("M4505S"));

        DriveReply *a = m_drive->readParameters({});
        DriveReply *b = other->readParameters({}); // pipelined on the bus with a
        WAIT_OK(a);
        WAIT_OK(b);
        QCOMPARE(a->parameters().size(), 9);
        QCOMPARE(b->parameters().size(), 7); // no gears on the M4505S
        QVERIFY(b->info().value(QStringLiteral("notReadable")).toList().contains(int(CmdSkipCrcCheck)));

        DriveReply *w = other->writeParameters(
            {{CmdSetHomingSpeed, 7000}, {CmdFixedLengthReplies, 1}, {CmdCanBitrate, 8}});
        WAIT_OK(w);
        QVERIFY(w->writeResults().value(0).verified);
        QVERIFY(!w->writeResults().value(1).readable);
        QCOMPARE(other->lastWritten(CmdCanBitrate).value_or(-1), 8);
        SimShuokeCanDevice *sim7 = static_cast<SimShuokeCanDevice *>(m_bench->bus()->device(1));
        QCOMPARE(sim7->drive().setting(CmdSetHomingSpeed), 7000);
        QCOMPARE(sim7->drive().setting(CmdCanBitrate), 8);
        QCOMPARE(sim7->drive().config().canBitrateCode, kDefaultCanBitrateCode); // after restart only
        QCOMPARE(m_sim->drive().setting(CmdSetHomingSpeed), 5000);               // the other drive
    }

    void refusedBeforeSending()
    {
        QVERIFY(setUp({config()}));
        const int tx = m_bench->txCount();
        QList<DriveReply *> replies;
        replies << m_drive->writeParameters({{CmdSetAcceleration, 100001}});
        replies << m_drive->sendCommand(CmdSetIoSubstitution, QByteArray::fromHex("01020304050607")); // 7 bytes
        replies << m_drive->sendCommand(CmdSerialToCanEcho, QByteArray(5, '\1'));                     // serial only
        replies << m_drive->moveRelative(qint64(1) << 40, 0);
        for (DriveReply *r : replies) {
            QVERIFY(ShuokeSerialBench::wait(r));
            QVERIFY(r->error().isError());
        }
        QCOMPARE(replies.at(0)->error().code, ErrorCode::OutOfRange);
        QCOMPARE(replies.at(1)->error().code, ErrorCode::NotSupported);
        QVERIFY(replies.at(1)->error().message.contains(QStringLiteral("CAN")));
        QCOMPARE(replies.at(2)->error().code, ErrorCode::NotSupported);
        QCOMPARE(replies.at(3)->error().code, ErrorCode::OutOfRange);
        QTest::qWait(50);
        QCOMPARE(m_bench->txCount(), tx);
        QCOMPARE(m_sim->drive().requestCount(), 0);
        // 0x4D is the CAN-only echo: it goes through.
        DriveReply *echo = m_drive->sendCommand(CmdCanToSerialEcho, QByteArray::fromHex("0102030405"));
        WAIT_OK(echo);
        QCOMPARE(echo->info().value(QStringLiteral("replyData")).toByteArray(), QByteArray::fromHex("0102030405"));
    }

    void motion()
    {
        SimShuokeDrive::Config c = config();
        c.switches.leftLimit = -3000;
        c.switches.rightLimit = 3000;
        c.switches.origin = -1200;
        QVERIFY(setUp({c}));
        WAIT_OK(m_drive->refreshIdentity()); // M6505: closed-loop commands
        // jog and stop
        WAIT_OK(m_drive->jog(6000));
        QTRY_COMPARE_WITH_TIMEOUT(channel(QStringLiteral("speed")), 6000.0, 3000);
        WAIT_OK(m_drive->stop(false));
        QTRY_VERIFY_WITH_TIMEOUT(!running(), 3000);
        // emergency stop
        WAIT_OK(m_drive->jog(-6000));
        QTRY_COMPARE_WITH_TIMEOUT(channel(QStringLiteral("speed")), -6000.0, 3000);
        WAIT_OK(m_drive->stop(true));
        QCOMPARE(m_sim->drive().axis().speed(), 0.0);
        // relative and absolute moves
        WAIT_OK(m_drive->setPosition(0));
        WAIT_OK(m_drive->moveRelative(1234, 20000));
        QTRY_VERIFY_WITH_TIMEOUT(!running(), 5000);
        QCOMPARE(channel(QStringLiteral("position")), 1234.0);
        QCOMPARE(channel(QStringLiteral("closed-loop-position")), 1234.0);
        WAIT_OK(m_drive->moveAbsolute(-500, 0)); // M6505: 0x57
        QTRY_VERIFY_WITH_TIMEOUT(!running(), 5000);
        QCOMPARE(channel(QStringLiteral("closed-loop-position")), -500.0);
        // homing: negative first finds the origin at -1200 before the left limit
        WAIT_OK(m_drive->home(false));
        QTRY_VERIFY_WITH_TIMEOUT(!running(), 5000);
        QVERIFY(std::llabs(m_sim->drive().axis().motorPosition() - -1200) <= 10);
        QCOMPARE(channel(QStringLiteral("position")), 0.0);
    }

    void failureCodeSurfaces()
    {
        SimShuokeDrive::Config c = config();
        c.byteOrder = ByteOrder::BigEndian;
        QVERIFY(setUp({c}));
        DriveReply *r = m_drive->jog(1000); // 0x000003E8 read big-endian: far beyond 100000
        QVERIFY(ShuokeSerialBench::wait(r));
        QCOMPARE(r->error().code, ErrorCode::DriveException);
        QCOMPARE(r->error().driveCode, int(FailureOutOfRange));
        m_drive->stop(true);
    }

    void byteOrderFlip()
    {
        SimShuokeDrive::Config c = config();
        c.byteOrder = ByteOrder::BigEndian;
        QVERIFY(setUp({c}, {{QStringLiteral("shuoke.byteOrder"), QStringLiteral("big")}}));
        WAIT_OK(m_drive->writeParameters({{CmdSetStartSpeed, 777}}));
        QCOMPARE(m_sim->drive().setting(CmdSetStartSpeed), 777);
        WAIT_OK(m_drive->jog(-1500));
        QTRY_COMPARE_WITH_TIMEOUT(channel(QStringLiteral("speed")), -1500.0, 3000);
        WAIT_OK(m_drive->stop(true));
    }

    void extendedFrames()
    {
        SimShuokeDrive::Config c = config(Model::M6505, 5);
        c.canExtended = true;
        QVERIFY(setUp({c}, {{QStringLiteral("shuoke.canFrame"), QStringLiteral("extended")}}));
        DriveReply *r = m_drive->readParameters({CmdSetMaxSpeed});
        WAIT_OK(r);
        QCOMPARE(r->parameters().value(CmdSetMaxSpeed), 10000);
        bool sawExtended = false;
        for (const TrafficRecord &rec : m_bench->records())
            sawExtended = sawExtended || (rec.isCan && rec.canExtended && rec.canId == 5);
        QVERIFY(sawExtended);
    }

    void discoveryByBroadcast()
    {
        QVERIFY(setUp({config(Model::M6505, 12), config(Model::M4505, 3)}));
        ScanOptions o;
        o.listenMs = 300;
        Discovery *d = m_bench->connection()->createDiscovery(o);
        QSignalSpy finished(d, &Discovery::finished);
        d->start();
        QVERIFY(finished.wait(3000));
        QVERIFY(!finished.first().first().value<Error>().isError());
        QCOMPARE(d->results().size(), 2);
        QList<int> addresses{d->results().at(0).address, d->results().at(1).address};
        // CAN arbitration: the lower identifier wins, its reply comes first.
        QCOMPARE(addresses, (QList<int>{3, 12}));
        QCOMPARE(d->results().first().bitrate, 100000);
        QCOMPARE(d->results().first().framing, QStringLiteral("can"));
        int broadcasts = 0;
        for (const TrafficRecord &r : m_bench->records())
            if (r.direction == TrafficRecord::Direction::Tx && r.canId == 0)
                ++broadcasts;
        QCOMPARE(broadcasts, 1);
    }

    void dropRecovery()
    {
        QVERIFY(setUp({config()}));
        FaultSettings f;
        f.dropRate = 0.3;
        f.seed = 3;
        m_sim->faults().setSettings(f);
        auto *can = qobject_cast<ShuokeCanTransport *>(m_bench->backend()->transport());
        for (int i = 0; i < 3; ++i) {
            DriveReply *r = m_drive->readParameters({});
            WAIT_OK(r);
            QCOMPARE(r->parameters().value(CmdSetDeceleration), 50000);
        }
        QVERIFY(m_bench->bus()->stats().framesDropped > 0);
        QVERIFY(can->link()->retryCount() > 0);
    }

    void stopAll()
    {
        QVERIFY(setUp({config(Model::M6505, 1), config(Model::M4505, 2)}));
        auto *second = static_cast<SimShuokeCanDevice *>(m_bench->bus()->device(1));
        WAIT_OK(m_drive->jog(3000));
        // No host object for drive 2: only the broadcast can stop it.
        WAIT_OK(m_drive->sendCommand(CmdRunSpeed, encodeInt32(3000), true, 2));
        QTRY_VERIFY_WITH_TIMEOUT(m_sim->drive().axis().speed() == 3000 && second->drive().axis().speed() == 3000, 3000);
        m_bench->backend()->stopAll();
        QTRY_VERIFY_WITH_TIMEOUT(!m_sim->drive().axis().isRunning() && !second->drive().axis().isRunning(), 2000);
        QVERIFY(!m_drive->isJogging());
    }
};

QTEST_GUILESS_MAIN(TestShuokeCanLink)
#include "tst_shuokecanlink.moc"
