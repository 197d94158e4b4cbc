// The shuoke family end to end in RTU framing: the real ShuokeBackend on QSerialPort over a
// pty, against simulated drives on a SimSerialBus.
#include <QtTest>

#include "core/drive/driveconnection.h"
#include "core/drive/drivereply.h"
#include "core/drive/shuoke/shuokebackend.h"
#include "core/drive/shuoke/shuokedrive.h"
#include "core/drive/shuoke/shuokeserialtransport.h"
#include "core/link/linkreply.h"
#include "core/link/seriallink.h"
#include "core/protocol/shuoke/shuokertu.h"
#include "sim/bus/simserialbus.h"
#include "tests/support/driveprobe.h"
#include "tests/support/shuokeserialbench.h"
#include "tests/support/waitok.h"

#include <cmath>
#include <memory>

using namespace dd;
using namespace dd::shuoke;

class TestShuokeSerialRtu : public QObject
{
    Q_OBJECT

    std::unique_ptr<ShuokeSerialBench> m_bench;
    SimShuokeSerialDevice *m_sim = nullptr;
    ShuokeDrive *m_drive = nullptr;

    static SimShuokeDrive::Config config(Model model = Model::M6505, quint8 address = 1)
    {
        SimShuokeDrive::Config c;
        c.model = model;
        c.address = address;
        c.powerUpWindowMs = 0;
        return c;
    }

    // One simulated drive at address 1 and the host connected to it.
    bool setUp(const SimShuokeDrive::Config &c, const QVariantMap &options = {}, int baud = 9600)
    {
        ConnectionSettings s;
        s.framing = QStringLiteral("rtu");
        s.baud = baud;
        s.options = options;
        m_bench = ShuokeSerialBench::create({c}, s);
        if (!m_bench)
            return false;
        m_sim = m_bench->devices().first();
        m_drive = m_bench->drive(c.address);
        m_drive->setJogLeaseMs(60000);
        return m_drive != nullptr;
    }

    double channel(const QString &id) { return test::readChannel(m_drive, id); }

    bool running() { return test::readRunning(m_drive); }

private slots:
    void cleanup()
    {
        m_bench.reset();
        m_sim = nullptr;
        m_drive = nullptr;
    }

    void identityDetectsModel_data()
    {
        QTest::addColumn<int>("model");
        QTest::newRow("M6505") << int(Model::M6505);
        QTest::newRow("M4505") << int(Model::M4505);
        QTest::newRow("M4505S") << int(Model::M4505S);
    }
    void identityDetectsModel()
    {
        QFETCH(int, model);
        QVERIFY(setUp(config(Model(model))));
        QVERIFY(!m_drive->model());
        DriveReply *r = m_drive->refreshIdentity();
        WAIT_OK(r);
        QCOMPARE(m_drive->identity().model, modelName(Model(model)));
        QCOMPARE(r->info().value(QStringLiteral("baudCode")).toInt(), 6);
        QVERIFY(m_drive->status().online);
        QCOMPARE(m_drive->hasCapability(Capability::Home), Model(model) != Model::M4505);
        QVERIFY(!m_drive->hasCapability(Capability::Enable));
        QVERIFY(m_drive->unsupportedReason(Capability::Enable).contains(QStringLiteral("enable")));
        const bool closedLoop = Model(model) == Model::M6505;
        bool hasError = false;
        for (const ChannelInfo &c : m_drive->channels())
            hasError = hasError || c.id == QLatin1String("position-error");
        QCOMPARE(hasError, closedLoop);
    }

    void readAllParameters()
    {
        QVERIFY(setUp(config()));
        m_sim->drive().setSetting(CmdSetHomingSpeed, 4321);
        WAIT_OK(m_drive->refreshIdentity()); // detects the M6505
        DriveReply *r = m_drive->readParameters({});
        WAIT_OK(r);
        const QMap<int, qint64> p = r->parameters();
        QCOMPARE(p.size(), 9); // the readable pairs of an M6505
        QCOMPARE(p.value(CmdSetBaudCode), 6);
        QCOMPARE(p.value(CmdSetStartSpeed), 500);
        QCOMPARE(p.value(CmdSetMaxSpeed), 10000);
        QCOMPARE(p.value(CmdSetHomingSpeed), 4321);
        QCOMPARE(p.value(CmdSetGearDenominator), 1);
        const QVariantList notReadable = r->info().value(QStringLiteral("notReadable")).toList();
        QVERIFY(notReadable.contains(int(CmdEncoderAbTolerance)));
        QVERIFY(notReadable.contains(int(CmdMotionDirection)));
        QVERIFY(!notReadable.contains(int(CmdSkipCrcCheck))); // M4505S only
    }

    void writeAndVerify()
    {
        QVERIFY(setUp(config()));
        DriveReply *r = m_drive->writeParameters(
            {{CmdSetStartSpeed, 1234}, {CmdSetMaxSpeed, 20000}, {CmdSetGearNumerator, 3}});
        WAIT_OK(r);
        QCOMPARE(r->writeResults().size(), 3);
        for (const ParameterWriteResult &w : r->writeResults()) {
            QVERIFY2(w.written && w.verified, qPrintable(w.error));
            QCOMPARE(w.readBack, w.requested);
        }
        QCOMPARE(m_sim->drive().setting(CmdSetStartSpeed), 1234);
        QCOMPARE(m_sim->drive().setting(CmdSetMaxSpeed), 20000);
        QCOMPARE(m_sim->drive().setting(CmdSetGearNumerator), 3);
    }

    void writeOnlyKeptAsLastWritten()
    {
        QVERIFY(setUp(config()));
        QVERIFY(!m_drive->lastWritten(CmdEncoderAbTolerance));
        DriveReply *r = m_drive->writeParameters({{CmdEncoderAbTolerance, 321}, {CmdMotionDirection, 1}});
        WAIT_OK(r);
        for (const ParameterWriteResult &w : r->writeResults()) {
            QVERIFY(w.written);
            QVERIFY(!w.readable);
            QVERIFY(!w.verified);
            QVERIFY(w.error.contains(QStringLiteral("Not readable")));
        }
        QCOMPARE(m_sim->drive().setting(CmdEncoderAbTolerance), 321);
        QCOMPARE(m_sim->drive().setting(CmdMotionDirection), 1);
        QCOMPARE(m_drive->lastWritten(CmdEncoderAbTolerance).value_or(-1), 321);

        const int tx = m_bench->txCount();
        DriveReply *read = m_drive->readParameters({CmdEncoderAbTolerance});
        WAIT_OK(read);
        QVERIFY(read->parameters().isEmpty());
        QCOMPARE(m_bench->txCount(), tx); // nothing can read it: nothing was sent
        const QVariantMap last = read->info().value(QStringLiteral("lastWritten")).toMap();
        QCOMPARE(last.value(QString::number(CmdEncoderAbTolerance)).toLongLong(), 321);
    }

    void outOfRangeNothingOnWire()
    {
        QVERIFY(setUp(config(Model::M4505), {{QStringLiteral("shuoke.model"), QStringLiteral("M4505")}}));
        const int tx = m_bench->txCount();
        const int seen = m_sim->drive().requestCount();
        QList<DriveReply *> replies;
        replies << m_drive->writeParameters({{CmdSetMaxSpeed, 100001}});
        replies << m_drive->writeParameters({{CmdSetStartSpeed, 10}, {CmdSetGearDenominator, 0}});
        replies << m_drive->writeParameters({{CmdSetBaudCode, 9}});
        replies << m_drive->jog(100001);
        replies << m_drive->moveRelative(100, 200000);
        replies << m_drive->home(true); // M4505: no homing command
        replies << m_drive->sendCommand(CmdSetHomingSpeed, encodeUInt32(10));
        for (DriveReply *r : replies) {
            QVERIFY(ShuokeSerialBench::wait(r));
            QVERIFY(r->error().isError());
            QVERIFY2(r->error().code == ErrorCode::OutOfRange || r->error().code == ErrorCode::NotSupported,
                     qPrintable(r->error().message));
        }
        QCOMPARE(replies.at(0)->error().code, ErrorCode::OutOfRange);
        QCOMPARE(replies.at(5)->error().code, ErrorCode::NotSupported);
        QTest::qWait(100);
        QCOMPARE(m_bench->txCount(), tx);
        QCOMPARE(m_sim->drive().requestCount(), seen);
        QCOMPARE(m_sim->drive().setting(CmdSetStartSpeed), 500); // all-or-nothing
    }

    void jogRunsAndStopStops()
    {
        QVERIFY(setUp(config()));
        WAIT_OK(m_drive->jog(-4000));
        QTRY_COMPARE_WITH_TIMEOUT(channel(QStringLiteral("speed")), -4000.0, 3000);
        QVERIFY(running());
        QVERIFY(m_sim->drive().axis().motorPosition() < 0);
        WAIT_OK(m_drive->stop(false));
        QTRY_COMPARE_WITH_TIMEOUT(channel(QStringLiteral("speed")), 0.0, 3000);
        QTRY_VERIFY_WITH_TIMEOUT(!running(), 3000);
        const double at = channel(QStringLiteral("position"));
        QCOMPARE(double(m_sim->drive().axis().absolutePosition()), at);
    }

    void jogLeaseStopsTheAxis()
    {
        QVERIFY(setUp(config()));
        m_drive->setJogLeaseMs(300);
        QSignalSpy expired(m_drive, &Drive::jogLeaseExpired);
        WAIT_OK(m_drive->jog(3000));
        QVERIFY(expired.wait(2000));
        QTRY_VERIFY_WITH_TIMEOUT(!m_sim->drive().axis().isRunning(), 3000);
    }

    void emergencyStop()
    {
        QVERIFY(setUp(config()));
        WAIT_OK(m_drive->jog(8000));
        QTRY_COMPARE_WITH_TIMEOUT(channel(QStringLiteral("speed")), 8000.0, 3000);
        WAIT_OK(m_drive->stop(true));
        // 0x3C: speed 0 at once (a deceleration from 8000 at 50000/s² would take 160 ms)
        QCOMPARE(m_sim->drive().axis().speed(), 0.0);
        QCOMPARE(m_sim->drive().requestCommands().last(), quint8(CmdEmergencyStop));
    }

    void relativeMoveEndsOnTarget()
    {
        QVERIFY(setUp(config()));
        WAIT_OK(m_drive->moveRelative(3000, 8000));
        QCOMPARE(m_sim->drive().setting(CmdSetMaxSpeed), 8000);
        QTRY_VERIFY_WITH_TIMEOUT(!running(), 5000);
        QCOMPARE(channel(QStringLiteral("position")), 3000.0);
        QCOMPARE(channel(QStringLiteral("closed-loop-position")), 3000.0);
        QCOMPARE(channel(QStringLiteral("position-error")), 0.0);
        WAIT_OK(m_drive->moveRelative(-1000, 0));
        QTRY_VERIFY_WITH_TIMEOUT(!running(), 5000);
        QCOMPARE(channel(QStringLiteral("position")), 2000.0);
    }

    void absoluteMove_data()
    {
        QTest::addColumn<int>("model");
        QTest::newRow("M6505 closed loop 0x57") << int(Model::M6505);
        QTest::newRow("M4505 from 0x37") << int(Model::M4505);
    }
    void absoluteMove()
    {
        QFETCH(int, model);
        QVERIFY(setUp(config(Model(model)), {{QStringLiteral("shuoke.model"), modelName(Model(model))}}));
        m_sim->drive().axis().placeAt(500);
        DriveReply *r = m_drive->moveAbsolute(-700, 9000);
        WAIT_OK(r);
        QCOMPARE(r->info().value(QStringLiteral("method")).toString(),
                 Model(model) == Model::M6505 ? QStringLiteral("closed-loop-absolute")
                                              : QStringLiteral("relative-from-position"));
        QTRY_VERIFY_WITH_TIMEOUT(!running(), 5000);
        QCOMPARE(channel(QStringLiteral("position")), -700.0);
        QCOMPARE(m_sim->drive().axis().motorPosition(), -200);
    }

    void homingReversesAtLimitAndZeroes()
    {
        SimShuokeDrive::Config c = config();
        c.switches.leftLimit = -2000;
        c.switches.rightLimit = 6000;
        c.switches.origin = 1500;
        QVERIFY(setUp(c));
        WAIT_OK(m_drive->writeParameters({{CmdSetHomingSpeed, 10000}}));
        WAIT_OK(m_drive->jog(5000));
        QTRY_VERIFY_WITH_TIMEOUT(m_sim->drive().axis().motorPosition() > 2500, 3000);
        WAIT_OK(m_drive->stop(true));
        const qint64 start = m_sim->drive().axis().motorPosition();
        QVERIFY(start > 1500);

        WAIT_OK(m_drive->home(true)); // positive first: right limit, reverse, origin
        QTRY_VERIFY_WITH_TIMEOUT(m_sim->drive().axis().rightLimit(), 5000);
        QVERIFY(m_sim->drive().axis().isHoming());
        QTRY_VERIFY_WITH_TIMEOUT(!running(), 8000);
        QVERIFY(!m_sim->drive().axis().homingFailed());
        QVERIFY(std::llabs(m_sim->drive().axis().motorPosition() - 1500) <= 10);
        QCOMPARE(channel(QStringLiteral("position")), 0.0);
        QCOMPARE(channel(QStringLiteral("closed-loop-position")), 0.0);
        QCOMPARE(channel(QStringLiteral("relative-position")), 0.0);
        DriveReply *st = m_drive->readAlarm();
        WAIT_OK(st);
        QVERIFY(st->info().value(QStringLiteral("origin")).toBool());
        QVERIFY(!st->info().value(QStringLiteral("rightLimit")).toBool());
    }

    void limitStopsJog()
    {
        SimShuokeDrive::Config c = config();
        c.switches.leftLimit = -800;
        QVERIFY(setUp(c));
        WAIT_OK(m_drive->jog(-6000));
        QTRY_VERIFY_WITH_TIMEOUT(!running(), 3000);
        DriveReply *st = m_drive->readAlarm();
        WAIT_OK(st);
        QVERIFY(st->info().value(QStringLiteral("leftLimit")).toBool());
        QVERIFY(st->info().value(QStringLiteral("conditions")).toStringList().contains(QStringLiteral("left-limit")));
        QVERIFY(m_sim->drive().axis().motorPosition() <= -800);
        QVERIFY(m_sim->drive().axis().motorPosition() > -1000);
    }

    void failureCodesSurface()
    {
        // The host believes M6505; the drive is an M4505: 0x3E is an unknown command there.
        QVERIFY(setUp(config(Model::M4505), {{QStringLiteral("shuoke.model"), QStringLiteral("M6505")}}));
        DriveReply *home = m_drive->home(false);
        QVERIFY(ShuokeSerialBench::wait(home));
        QCOMPARE(home->error().code, ErrorCode::DriveException);
        QCOMPARE(home->error().driveCode, 0x03);
        QVERIFY(home->error().message.contains(QStringLiteral("0x03")));
        QCOMPARE(m_drive->lastFailureCode(), 0x03);

        struct Case
        {
            quint8 command;
            QByteArray data;
            int address;
            int code;
        };
        const QList<Case> cases{
            {CmdSetMaxSpeed, QByteArray(3, '\0'), -1, FailureTimeoutOrLength},
            {CmdSetMaxSpeed, encodeUInt32(100001), -1, FailureOutOfRange},
            {CmdSetMaxSpeed, encodeUInt32(100), 0, FailureNoBroadcast},
            {0x70, {}, -1, FailureUnknownCommand},
        };
        for (const Case &c : cases) {
            DriveReply *r = m_drive->sendCommand(c.command, c.data, false, c.address);
            QVERIFY(ShuokeSerialBench::wait(r));
            QCOMPARE(r->error().code, ErrorCode::DriveException);
            QCOMPARE(r->error().driveCode, c.code);
            QCOMPARE(r->info().value(QStringLiteral("replyCommand")).toInt(), c.command | 0x80);
        }

        // 0x02: a request whose CRC is wrong, sent as raw bytes on the link.
        auto *transport = qobject_cast<ShuokeSerialTransport *>(m_bench->backend()->transport());
        QVERIFY(transport);
        const Frame request = Frame::make(1, CmdGetMaxSpeed);
        QByteArray bytes = *encodeRtu(request).value;
        bytes[bytes.size() - 1] = static_cast<char>(bytes.back() ^ 0x5A);
        SerialRequest raw;
        raw.bytes = bytes;
        raw.matcher = ShuokeSerialTransport::rtuMatcher(request);
        raw.retries = 0;
        LinkReply *lr = transport->link()->send(raw);
        QSignalSpy done(lr, &LinkReply::finished);
        QVERIFY(done.wait(3000));
        QVERIFY2(!lr->error().isError(), qPrintable(lr->error().message));
        const Decoded<Frame> reply = decodeRtu(lr->frame());
        QVERIFY(reply.ok());
        QVERIFY(reply.value->failure);
        QCOMPARE(reply.value->failureCode, quint8(FailureChecksum));
    }

    void minimumGapBetweenCommands_data()
    {
        QTest::addColumn<int>("gapMs");
        QTest::addColumn<QString>("gapFrom");
        QTest::newRow("default 50 ms from the command") << -1 << QString();
        QTest::newRow("setting 15 ms from the command") << 15 << QStringLiteral("command");
        QTest::newRow("50 ms from the reply") << -1 << QStringLiteral("reply");
    }
    void minimumGapBetweenCommands()
    {
        QFETCH(int, gapMs);
        QFETCH(QString, gapFrom);
        QVariantMap options;
        if (gapMs >= 0)
            options.insert(QStringLiteral("shuoke.minGapMs"), gapMs);
        if (!gapFrom.isEmpty())
            options.insert(QStringLiteral("shuoke.gapFrom"), gapFrom);
        const bool fromReply = gapFrom == QLatin1String("reply");
        SimShuokeDrive::Config c = config();
        c.minCommandGapMs = gapMs >= 0 ? 10 : 50; // the drive's own limit (from each command)
        QVERIFY(setUp(c, options));
        const int expected = gapMs >= 0 ? gapMs : 50;
        m_bench->clearRecords();
        WAIT_OK(m_drive->readParameters({}));
        WAIT_OK(m_drive->readChannels({}));
        // Between the end of one transaction (its reply) and the next request.
        qint64 smallest = std::numeric_limits<qint64>::max();
        int gaps = 0;
        const QList<TrafficRecord> &rec = m_bench->records();
        for (int i = 1; i < rec.size(); ++i) {
            if (rec[i].direction != TrafficRecord::Direction::Tx
                || rec[i - 1].direction != TrafficRecord::Direction::Rx)
                continue;
            smallest = std::min(smallest, rec[i].timestampUs - rec[i - 1].timestampUs);
            ++gaps;
        }
        QVERIFY(gaps >= 15);
        // 3.5 characters at 9600 baud (4 ms) at least; from the reply: the whole gap.
        const qint64 quietUs = fromReply ? expected * 1000 : 3646;
        QVERIFY2(smallest >= quietUs - 500, qPrintable(QString::number(smallest)));
        if (!fromReply) // counted from the command: the reply's time is not added
            QVERIFY2(smallest < expected * 1000 - 5000, qPrintable(QString::number(smallest)));
        // The drive saw the commands `expected` apart (request arrival times), and every
        // one of them was taken.
        const QList<qint64> &t = m_sim->drive().requestTimesUs();
        QVERIFY(t.size() >= 15);
        qint64 closest = std::numeric_limits<qint64>::max();
        for (int i = 1; i < t.size(); ++i)
            closest = std::min(closest, t[i] - t[i - 1]);
        QVERIFY2(closest >= expected * 1000, qPrintable(QString::number(closest)));
        QCOMPARE(m_sim->drive().tooSoonCount(), 0);
    }

    void driveIgnoresCommandsSentTooSoon()
    {
        QVERIFY(setUp(config(), {{QStringLiteral("shuoke.minGapMs"), 0}}));
        qobject_cast<ShuokeSerialTransport *>(m_bench->backend()->transport())->link()->setRetries(0);
        DriveReply *r = m_drive->readParameters({});
        QVERIFY(ShuokeSerialBench::wait(r, 10000));
        QCOMPARE(r->error().code, ErrorCode::Timeout);
        QVERIFY(r->parameters().size() < 9);
        QVERIFY(m_sim->drive().tooSoonCount() > 0);
    }

    void dropAndCorruptRecovery()
    {
        SimShuokeDrive::Config c = config();
        c.baudCode = 8;
        QVERIFY(setUp(c, {}, 38400));
        FaultSettings f;
        f.dropRate = 0.25;
        f.corruptRate = 0.25;
        f.seed = 7;
        m_sim->faults().setSettings(f);
        SerialLink *link = qobject_cast<ShuokeSerialTransport *>(m_bench->backend()->transport())->link();
        link->setRetries(8);
        for (int i = 0; i < 4; ++i) {
            DriveReply *r = m_drive->readParameters({});
            WAIT_OK(r);
            QCOMPARE(r->parameters().value(CmdSetMaxSpeed), 10000);
            QCOMPARE(r->parameters().size(), 9);
        }
        QVERIFY(m_bench->bus()->stats().framesDropped > 0);
        QVERIFY(m_bench->bus()->stats().framesCorrupted > 0);
        QVERIFY(link->timeoutCount() > 0);
        QVERIFY(link->retryCount() > 0);
    }

    void byteOrderFlip()
    {
        SimShuokeDrive::Config c = config();
        c.byteOrder = ByteOrder::BigEndian;
        QVERIFY(setUp(c, {{QStringLiteral("shuoke.byteOrder"), QStringLiteral("big")}}));
        WAIT_OK(m_drive->writeParameters({{CmdSetMaxSpeed, 20000}}));
        QCOMPARE(m_sim->drive().setting(CmdSetMaxSpeed), 20000);
        WAIT_OK(m_drive->moveRelative(-1500, 0));
        QTRY_VERIFY_WITH_TIMEOUT(!running(), 5000);
        QCOMPARE(channel(QStringLiteral("position")), -1500.0);
        QCOMPARE(m_sim->drive().axis().motorPosition(), -1500);
    }

    void byteOrderMismatchIsRefusedByTheDrive()
    {
        SimShuokeDrive::Config c = config();
        c.byteOrder = ByteOrder::BigEndian;
        QVERIFY(setUp(c));                                                    // host little-endian
        DriveReply *r = m_drive->writeParameters({{CmdSetMaxSpeed, 100000}}); // A0 86 01 00
        QVERIFY(ShuokeSerialBench::wait(r));
        QCOMPARE(r->error().code, ErrorCode::DriveException);
        QCOMPARE(r->error().driveCode, int(FailureOutOfRange));
        QVERIFY(!r->writeResults().value(0).written);
    }

    void baudCodeWriteSwitchesTheLink()
    {
        QVERIFY(setUp(config()));
        DriveReply *r = m_drive->writeParameters({{CmdSetBaudCode, 7}});
        WAIT_OK(r);
        QVERIFY(r->writeResults().value(0).verified);
        QCOMPARE(m_bench->backend()->transport()->baud(), 19200);
        QCOMPARE(m_sim->baud(), 19200);
        WAIT_OK(m_drive->readParameters({CmdSetMaxSpeed}));
    }

    void powerUpWindowTalks9600()
    {
        SimShuokeDrive::Config c = config();
        c.baudCode = 7;
        c.powerUpWindowMs = 1500;
        QVERIFY(setUp(c));                   // host at 9600
        WAIT_OK(m_drive->refreshIdentity()); // within the window
        QTRY_COMPARE_WITH_TIMEOUT(m_sim->baud(), 19200, 3000);
        DriveReply *late = m_drive->sendCommand(CmdHandshake);
        QVERIFY(ShuokeSerialBench::wait(late, 8000));
        QCOMPARE(late->error().code, ErrorCode::Timeout);
        QVERIFY(m_bench->backend()->transport()->setBaud(19200));
        WAIT_OK(m_drive->sendCommand(CmdHandshake));
    }

    void addressChangeAfterRestart()
    {
        QVERIFY(setUp(config()));
        DriveReply *r = m_drive->changeAddress(9);
        WAIT_OK(r);
        QVERIFY(r->info().value(QStringLiteral("effectiveAfterRestart")).toBool());
        WAIT_OK(m_drive->sendCommand(CmdHandshake)); // still at 1
        m_sim->powerCycle();
        ShuokeDrive *moved = m_bench->drive(9);
        WAIT_OK(moved->sendCommand(CmdHandshake));
        DriveReply *old = m_drive->sendCommand(CmdHandshake);
        QVERIFY(ShuokeSerialBench::wait(old, 8000));
        QCOMPARE(old->error().code, ErrorCode::Timeout);
    }

    void stopAllBroadcast()
    {
        m_bench = std::make_unique<ShuokeSerialBench>();
        QString error;
        if (!m_bench->start(&error))
            QSKIP(qPrintable(error));
        SimShuokeSerialDevice *a = m_bench->addDrive(config(Model::M6505, 3));
        SimShuokeSerialDevice *b = m_bench->addDrive(config(Model::M4505, 4));
        ConnectionSettings s;
        QVERIFY2(m_bench->connectHost(s, &error), qPrintable(error));
        m_bench->drive(3)->setJogLeaseMs(60000);
        WAIT_OK(m_bench->drive(3)->jog(2000));
        // No host object for drive 4: only the broadcast can stop it.
        WAIT_OK(m_bench->drive(3)->sendCommand(CmdRunSpeed, encodeInt32(-2000), true, 4));
        QTRY_VERIFY_WITH_TIMEOUT(a->drive().axis().speed() == 2000 && b->drive().axis().speed() == -2000, 3000);
        m_bench->backend()->stopAll();
        QTRY_VERIFY_WITH_TIMEOUT(!a->drive().axis().isRunning() && !b->drive().axis().isRunning(), 3000);
        QVERIFY(!m_bench->drive(3)->isJogging());
        QVERIFY(b->drive().requestCommands().contains(quint8(CmdEmergencyStop)));
    }
};

QTEST_GUILESS_MAIN(TestShuokeSerialRtu)
#include "tst_shuokeserialrtu.moc"
