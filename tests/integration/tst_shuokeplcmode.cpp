// The shuoke family end to end in PLC mode: the real ShuokeBackend on ModbusLink
// (on SerialLink) over a pty, against simulated drives answering Modbus RTU on
// the mapped registers.
#include <QtTest>

#include "core/drive/driveconnection.h"
#include "core/drive/drivereply.h"
#include "core/drive/shuoke/shuokebackend.h"
#include "core/drive/shuoke/shuokedrive.h"
#include "core/drive/shuoke/shuokeplctransport.h"
#include "core/link/modbuslink.h"
#include "sim/bus/simserialbus.h"
#include "tests/support/driveprobe.h"
#include "tests/support/shuokeserialbench.h"
#include "tests/support/waitok.h"

#include <cmath>
#include <memory>

using namespace dd;
using namespace dd::shuoke;

class TestShuokePlcMode : public QObject
{
    Q_OBJECT

    std::unique_ptr<ShuokeSerialBench> m_bench;
    SimShuokeSerialDevice *m_sim = nullptr;
    ShuokeDrive *m_drive = nullptr;

    static SimShuokeDrive::Config config(quint8 address = 1, quint16 base = 0x1000)
    {
        SimShuokeDrive::Config c;
        c.address = address;
        c.plcBase = base;
        c.powerUpWindowMs = 0;
        c.baudCode = 7;
        return c;
    }

    bool setUp(const QList<SimShuokeDrive::Config> &drives, quint16 hostBase = 0x1000)
    {
        ConnectionSettings s;
        s.framing = QStringLiteral("plc");
        s.baud = 19200;
        s.options.insert(QStringLiteral("shuoke.plcBase"), QStringLiteral("0x%1").arg(hostBase, 0, 16));
        m_bench = ShuokeSerialBench::create(drives, s, SimShuokeSerialDevice::Framing::Plc);
        if (!m_bench)
            return false;
        if (!m_sim)
            m_sim = m_bench->devices().first();
        m_drive = m_bench->drive(drives.first().address);
        m_drive->setJogLeaseMs(60000);
        return true;
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

    void parameters()
    {
        QVERIFY(setUp({config()}));
        WAIT_OK(m_drive->refreshIdentity());
        QCOMPARE(m_drive->identity().model, QStringLiteral("M6505"));
        DriveReply *r = m_drive->readParameters({});
        WAIT_OK(r);
        QCOMPARE(r->parameters().size(), 9);
        QCOMPARE(r->parameters().value(CmdSetBaudCode), 7);
        QCOMPARE(r->parameters().value(CmdSetMaxSpeed), 10000);
        DriveReply *w = m_drive->writeParameters({{CmdSetStopSpeed, 900},
                                                  {CmdSetGearDenominator, 4},
                                                  {CmdEncoderDirection, 1},
                                                  {CmdNoEncoderMaxPulses, 6000}});
        WAIT_OK(w);
        QVERIFY(w->writeResults().value(0).verified);
        QVERIFY(w->writeResults().value(1).verified);
        QVERIFY(!w->writeResults().value(2).readable);
        QCOMPARE(m_sim->drive().setting(CmdSetStopSpeed), 900);
        QCOMPARE(m_sim->drive().setting(CmdSetGearDenominator), 4);
        QCOMPARE(m_sim->drive().setting(CmdEncoderDirection), 1); // one register
        QCOMPARE(m_sim->drive().setting(CmdNoEncoderMaxPulses), 6000);
        QCOMPARE(m_drive->lastWritten(CmdEncoderDirection).value_or(-1), 1);
        // Registers on the wire: base + command.
        bool sawRegister = false;
        for (const TrafficRecord &rec : m_bench->records())
            if (rec.direction == TrafficRecord::Direction::Tx && rec.bytes.size() >= 4 && rec.bytes.at(1) == 0x10)
                sawRegister = sawRegister
                    || (quint8(rec.bytes.at(2)) == 0x10 && quint8(rec.bytes.at(3)) == CmdSetStopSpeed);
        QVERIFY(sawRegister);
    }

    void unmappedCommandsAreRefusedBeforeSending()
    {
        QVERIFY(setUp({config()}));
        const int tx = m_bench->txCount();
        QList<DriveReply *> replies{m_drive->sendCommand(CmdHandshake),
                                    m_drive->readChannels({QStringLiteral("inputs")}),
                                    m_drive->sendCommand(CmdSetIoSubstitution, QByteArray::fromHex("0102")),
                                    m_drive->writeParameters({{CmdSetMaxSpeed, 100001}})};
        for (DriveReply *r : replies) {
            QVERIFY(ShuokeSerialBench::wait(r));
            QVERIFY(r->error().isError());
        }
        QCOMPARE(replies.at(0)->error().code, ErrorCode::NotSupported);
        QVERIFY(replies.at(0)->error().message.contains(QStringLiteral("RTU")));
        QCOMPARE(replies.at(1)->error().code, ErrorCode::NotSupported);
        QCOMPARE(replies.at(3)->error().code, ErrorCode::OutOfRange);
        QTest::qWait(50);
        QCOMPARE(m_bench->txCount(), tx);
        bool inputs = false;
        for (const ChannelInfo &c : m_drive->channels())
            inputs = inputs || c.id == QLatin1String("inputs");
        QVERIFY(!inputs);
    }

    void motion()
    {
        SimShuokeDrive::Config c = config();
        c.switches.leftLimit = -4000;
        c.switches.origin = -900;
        QVERIFY(setUp({c}));
        WAIT_OK(m_drive->jog(-5000));
        QTRY_COMPARE_WITH_TIMEOUT(channel(QStringLiteral("speed")), -5000.0, 3000);
        WAIT_OK(m_drive->stop(false));
        QTRY_VERIFY_WITH_TIMEOUT(!running(), 3000);
        WAIT_OK(m_drive->jog(5000));
        QTRY_COMPARE_WITH_TIMEOUT(channel(QStringLiteral("speed")), 5000.0, 3000);
        WAIT_OK(m_drive->stop(true));
        QCOMPARE(m_sim->drive().axis().speed(), 0.0);
        WAIT_OK(m_drive->setPosition(0));
        WAIT_OK(m_drive->moveRelative(2500, 12000));
        QTRY_VERIFY_WITH_TIMEOUT(!running(), 5000);
        QCOMPARE(channel(QStringLiteral("position")), 2500.0);
        WAIT_OK(m_drive->home(false));
        QTRY_VERIFY_WITH_TIMEOUT(!running(), 8000);
        QVERIFY(std::llabs(m_sim->drive().axis().motorPosition() - -900) <= 10);
        QCOMPARE(channel(QStringLiteral("position")), 0.0);
    }

    void exceptionsCarryTheFailureCode()
    {
        QVERIFY(setUp({config()}));
        DriveReply *r = m_drive->sendCommand(CmdSetAcceleration, encodeUInt32(100001), false);
        QVERIFY(ShuokeSerialBench::wait(r));
        QCOMPARE(r->error().code, ErrorCode::DriveException);
        QCOMPARE(r->error().driveCode, int(FailureOutOfRange));
        QVERIFY(r->error().message.contains(QStringLiteral("Modbus exception 4")));
    }

    void wrongBaseIsAnException()
    {
        QVERIFY(setUp({config(1, 0x1000)}, 0x2000));
        DriveReply *r = m_drive->readParameters({CmdSetMaxSpeed});
        QVERIFY(ShuokeSerialBench::wait(r));
        QCOMPARE(r->error().code, ErrorCode::DriveException);
        QCOMPARE(r->error().driveCode, 2); // illegal data address
    }

    void minimumGap()
    {
        QVERIFY(setUp({config()}));
        m_bench->clearRecords();
        WAIT_OK(m_drive->readParameters({}));
        qint64 smallest = std::numeric_limits<qint64>::max();
        const QList<TrafficRecord> &rec = m_bench->records();
        int gaps = 0;
        for (int i = 1; i < rec.size(); ++i) {
            if (rec[i].direction == TrafficRecord::Direction::Tx
                && rec[i - 1].direction == TrafficRecord::Direction::Rx) {
                smallest = std::min(smallest, rec[i].timestampUs - rec[i - 1].timestampUs);
                ++gaps;
            }
        }
        QVERIFY(gaps >= 8);
        // The 50 ms count from each command (as the drive counts); after a reply only the
        // Modbus silence (3.5 characters, 4 ms at 9600) is kept.
        QVERIFY2(smallest >= 3500 && smallest < 45000, qPrintable(QString::number(smallest)));
        const QList<qint64> &t = m_sim->drive().requestTimesUs();
        QVERIFY(t.size() >= 8);
        for (int i = 1; i < t.size(); ++i)
            QVERIFY2(t[i] - t[i - 1] >= 50000, qPrintable(QString::number(t[i] - t[i - 1])));
        QCOMPARE(m_sim->drive().tooSoonCount(), 0);
    }

    void discovery()
    {
        QVERIFY(setUp({config(4), config(6)}));
        ScanOptions o;
        o.from = 1;
        o.to = 7;
        Discovery *d = m_bench->connection()->createDiscovery(o);
        QSignalSpy finished(d, &Discovery::finished);
        d->start();
        QVERIFY(finished.wait(30000));
        QCOMPARE(d->results().size(), 2);
        QCOMPARE(d->results().at(0).address, 4);
        QCOMPARE(d->results().at(1).address, 6);
        QCOMPARE(d->results().at(0).framing, QStringLiteral("plc"));
    }
};

QTEST_GUILESS_MAIN(TestShuokePlcMode)
#include "tst_shuokeplcmode.moc"
