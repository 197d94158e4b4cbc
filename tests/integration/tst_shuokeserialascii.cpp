// The shuoke family end to end in ASCII framing (both check-byte settings): the real
// ShuokeBackend on QSerialPort over a pty, against simulated drives on a SimSerialBus.
#include <QtTest>

#include "core/drive/drivereply.h"
#include "core/drive/shuoke/shuokebackend.h"
#include "core/drive/shuoke/shuokedrive.h"
#include "core/drive/shuoke/shuokeserialtransport.h"
#include "core/link/seriallink.h"
#include "core/protocol/shuoke/shuokeascii.h"
#include "sim/bus/simserialbus.h"
#include "tests/support/driveprobe.h"
#include "tests/support/shuokeserialbench.h"
#include "tests/support/waitok.h"

#include <cmath>
#include <memory>

using namespace dd;
using namespace dd::shuoke;

class TestShuokeSerialAscii : public QObject
{
    Q_OBJECT

    std::unique_ptr<ShuokeSerialBench> m_bench;
    SimShuokeSerialDevice *m_sim = nullptr;
    ShuokeDrive *m_drive = nullptr;

    bool setUp(AsciiCheck hostCheck, AsciiCheck driveCheck, Model model = Model::M6505)
    {
        SimShuokeDrive::Config c;
        c.model = model;
        c.address = 2;
        c.powerUpWindowMs = 0;
        ConnectionSettings s;
        s.framing = QStringLiteral("ascii");
        s.options.insert(QStringLiteral("shuoke.checksum"),
                         hostCheck == AsciiCheck::PlainSum ? QStringLiteral("sum") : QStringLiteral("twos-complement"));
        m_bench = ShuokeSerialBench::create({c}, s, SimShuokeSerialDevice::Framing::Ascii, driveCheck);
        if (!m_bench)
            return false;
        m_sim = m_bench->devices().first();
        m_drive = m_bench->drive(2);
        m_drive->setJogLeaseMs(60000);
        return true;
    }

    double channel(const QString &id) { return test::readChannel(m_drive, id); }

private slots:
    void cleanup()
    {
        m_bench.reset();
        m_sim = nullptr;
        m_drive = nullptr;
    }

    void seedExampleOnTheWire()
    {
        // The seed's worked example: change address 1 -> 2 is ":0122010226\r\n".
        const Decoded<QByteArray> line = encodeAscii(Frame::make(1, CmdChangeAddress, QByteArray(1, '\x02')));
        QVERIFY(line.ok());
        QCOMPARE(*line.value, QByteArray(":0122010226\r\n"));
    }

    void endToEnd_data()
    {
        QTest::addColumn<int>("check");
        QTest::newRow("plain sum (default)") << int(AsciiCheck::PlainSum);
        QTest::newRow("two's complement") << int(AsciiCheck::TwosComplement);
    }
    void endToEnd()
    {
        QFETCH(int, check);
        const AsciiCheck mode = AsciiCheck(check);
        QVERIFY(setUp(mode, mode));

        // identity, then every parameter
        WAIT_OK(m_drive->refreshIdentity());
        QCOMPARE(m_drive->identity().model, QStringLiteral("M6505"));
        DriveReply *read = m_drive->readParameters({});
        WAIT_OK(read);
        QCOMPARE(read->parameters().size(), 9);
        QCOMPARE(read->parameters().value(CmdSetAcceleration), 50000);

        // write + verify, and a write-only setting
        DriveReply *write = m_drive->writeParameters({{CmdSetDeceleration, 40000}, {CmdErrorCorrection, 1}});
        WAIT_OK(write);
        QVERIFY(write->writeResults().value(0).verified);
        QVERIFY(!write->writeResults().value(1).readable);
        QCOMPARE(m_drive->lastWritten(CmdErrorCorrection).value_or(-1), 1);
        QCOMPARE(m_sim->drive().setting(CmdSetDeceleration), 40000);
        QCOMPARE(m_sim->drive().setting(CmdErrorCorrection), 1);

        // motion
        WAIT_OK(m_drive->jog(2500));
        QTRY_COMPARE_WITH_TIMEOUT(channel(QStringLiteral("speed")), 2500.0, 3000);
        WAIT_OK(m_drive->stop(false));
        QTRY_COMPARE_WITH_TIMEOUT(channel(QStringLiteral("speed")), 0.0, 3000);

        // failure code
        DriveReply *bad = m_drive->sendCommand(CmdSetStopSpeed, encodeUInt32(200000), false);
        QVERIFY(ShuokeSerialBench::wait(bad));
        QCOMPARE(bad->error().code, ErrorCode::DriveException);
        QCOMPARE(bad->error().driveCode, int(FailureOutOfRange));

        // Every frame on the wire is ':' hex CR LF with the configured check byte.
        int frames = 0;
        for (const TrafficRecord &r : m_bench->records()) {
            if (r.direction == TrafficRecord::Direction::Discarded)
                continue;
            QVERIFY(r.bytes.startsWith(':'));
            QVERIFY(r.bytes.endsWith("\r\n"));
            const QByteArray bytes = QByteArray::fromHex(r.bytes.mid(1, r.bytes.size() - 3));
            QCOMPARE(asciiCheckByte(bytes.left(bytes.size() - 1), mode), quint8(bytes.back()));
            ++frames;
        }
        QVERIFY(frames > 20);
        QCOMPARE(m_sim->checksumErrors(), quint64(0));
    }

    void checkByteMismatch()
    {
        QVERIFY(setUp(AsciiCheck::PlainSum, AsciiCheck::TwosComplement));
        auto *link = qobject_cast<ShuokeSerialTransport *>(m_bench->backend()->transport())->link();
        link->setRetries(1);
        DriveReply *r = m_drive->sendCommand(CmdHandshake); // the drive skips the check of 0x20 ...
        QVERIFY(ShuokeSerialBench::wait(r));
        // ... but its reply carries its own check byte, which the host refuses.
        QCOMPARE(r->error().code, ErrorCode::ChecksumError);
        DriveReply *get = m_drive->sendCommand(CmdGetMaxSpeed);
        QVERIFY(ShuokeSerialBench::wait(get));
        QCOMPARE(get->error().code, ErrorCode::ChecksumError);
        QVERIFY(m_sim->checksumErrors() > 0); // the drive answered failure 0x02
        QVERIFY(link->checksumErrorCount() >= 2);
    }

    void corruptRepliesRecovered()
    {
        QVERIFY(setUp(AsciiCheck::TwosComplement, AsciiCheck::TwosComplement));
        FaultSettings f;
        f.corruptRate = 0.3;
        f.dropRate = 0.1;
        f.seed = 11;
        m_sim->faults().setSettings(f);
        qobject_cast<ShuokeSerialTransport *>(m_bench->backend()->transport())->link()->setRetries(8);
        for (int i = 0; i < 3; ++i) {
            DriveReply *r = m_drive->readChannels({QStringLiteral("position"), QStringLiteral("status")});
            WAIT_OK(r);
            QCOMPARE(r->samples().value(QStringLiteral("position")), 0.0);
        }
        QVERIFY(m_bench->bus()->stats().framesCorrupted > 0);
    }
};

QTEST_GUILESS_MAIN(TestShuokeSerialAscii)
#include "tst_shuokeserialascii.moc"
