// The simulated Shuoke drive without any I/O: the drive core (commands, failure codes,
// broadcasts, pending settings, power-up baud, state), the axis (limits, homing) and the
// serial adapter's drive-side framing (RTU, ASCII, PLC), fed bytes directly.
#include <QtTest>

#include "core/protocol/modbus/crc16.h"
#include "core/protocol/shuoke/shuokeascii.h"
#include "core/protocol/shuoke/shuokeplc.h"
#include "core/protocol/shuoke/shuokertu.h"
#include "sim/shuoke/simshuokedrive.h"
#include "sim/shuoke/simshuokeserialdevice.h"

using namespace dd;
using namespace dd::shuoke;

namespace {
constexpr qint64 DriveMs = 1000;

SimShuokeDrive::Config driveConfig(Model model = Model::M6505)
{
    SimShuokeDrive::Config c;
    c.model = model;
    c.powerUpWindowMs = 0;
    c.minCommandGapMs = 0; // many requests at the same instant below
    return c;
}

Frame req(quint8 cmd, const QByteArray &data = {}, quint8 address = 1)
{
    return Frame::make(address, cmd, data);
}
} // namespace

class TestSimShuokeDrive : public QObject
{
    Q_OBJECT

private slots:
    void failureCodes_data()
    {
        QTest::addColumn<int>("model");
        QTest::addColumn<int>("command");
        QTest::addColumn<QByteArray>("data");
        QTest::addColumn<int>("address");
        QTest::addColumn<int>("code"); // 0: success
        QTest::newRow("ok") << int(Model::M6505) << int(CmdSetMaxSpeed) << encodeUInt32(100000) << 1 << 0;
        QTest::newRow("length") << int(Model::M6505) << int(CmdSetMaxSpeed) << QByteArray(2, '\0') << 1 << 1;
        QTest::newRow("unknown") << int(Model::M6505) << 0x63 << QByteArray() << 1 << 3;
        QTest::newRow("M4505 has no 0x3E") << int(Model::M4505) << int(CmdHome) << QByteArray(1, '\0') << 1 << 3;
        QTest::newRow("M6505 has no 0x44") << int(Model::M6505) << int(CmdSetSpeedStep) << encodeUInt32(5) << 1 << 3;
        QTest::newRow("S-curve only on M4505S")
            << int(Model::M6505) << int(CmdHomeOrSCurveInt32) << encodeInt32(5) << 1 << 3;
        QTest::newRow("S-curve on M4505S")
            << int(Model::M4505S) << int(CmdHomeOrSCurveInt32) << encodeInt32(5) << 1 << 0;
        QTest::newRow("range") << int(Model::M6505) << int(CmdSetMaxSpeed) << encodeUInt32(100001) << 1 << 4;
        QTest::newRow("baud code 9") << int(Model::M6505) << int(CmdSetBaudCode) << QByteArray(1, '\x09') << 1 << 4;
        QTest::newRow("gear 0") << int(Model::M6505) << int(CmdSetGearDenominator) << encodeUInt32(0) << 1 << 4;
        QTest::newRow("broadcast set") << int(Model::M6505) << int(CmdSetMaxSpeed) << encodeUInt32(5) << 0 << 5;
        QTest::newRow("broadcast 255") << int(Model::M6505) << int(CmdGetMaxSpeed) << QByteArray() << 255 << 5;
    }
    void failureCodes()
    {
        QFETCH(int, model);
        QFETCH(int, command);
        QFETCH(QByteArray, data);
        QFETCH(int, address);
        QFETCH(int, code);
        SimShuokeDrive d(driveConfig(Model(model)));
        const auto reply = d.handle(req(quint8(command), data, quint8(address)), SimShuokeDrive::Medium::Serial, 0);
        QVERIFY(reply);
        QCOMPARE(reply->address, quint8(1));
        QCOMPARE(reply->command, quint8(command));
        QCOMPARE(reply->failure, code != 0);
        if (code)
            QCOMPARE(int(reply->failureCode), code);
    }

    void mediumRestrictions()
    {
        SimShuokeDrive d(driveConfig());
        auto r = d.handle(req(CmdSetIoSubstitution, QByteArray::fromHex("0102")), SimShuokeDrive::Medium::Can, 0);
        QCOMPARE(int(r->failureCode), 3);
        r = d.handle(req(CmdCanToSerialEcho, QByteArray(5, '\1')), SimShuokeDrive::Medium::Serial, 0);
        QCOMPARE(int(r->failureCode), 3);
        r = d.handle(req(CmdCanToSerialEcho, QByteArray(5, '\1')), SimShuokeDrive::Medium::Can, 0);
        QVERIFY(!r->failure);
        QCOMPARE(r->data, QByteArray(5, '\1'));
    }

    void broadcasts()
    {
        SimShuokeDrive d(driveConfig());
        QVERIFY(!d.handle(req(CmdGetMaxSpeed, {}, 2), SimShuokeDrive::Medium::Serial, 0)); // someone else
        QVERIFY(d.handle(req(CmdRunSpeed, encodeInt32(1000)), SimShuokeDrive::Medium::Serial, 0));
        d.advanceTo(200 * DriveMs);
        QVERIFY(d.axis().isRunning());
        QVERIFY(!d.handle(req(CmdEmergencyStop, {}, 0), SimShuokeDrive::Medium::Serial, 200 * DriveMs)); // acts, silent
        QCOMPARE(d.axis().speed(), 0.0);
        const auto who = d.handle(req(CmdQueryAddress, {}, 0), SimShuokeDrive::Medium::Serial, 201 * DriveMs);
        QVERIFY(who);
        QCOMPARE(who->address, quint8(1));
        SimShuokeDrive::Config only255 = driveConfig();
        only255.broadcasts = {255};
        SimShuokeDrive e(only255);
        QVERIFY(!e.handle(req(CmdQueryAddress, {}, 0), SimShuokeDrive::Medium::Serial, 0));
        QVERIFY(e.handle(req(CmdQueryAddress, {}, 255), SimShuokeDrive::Medium::Serial, 0));
    }

    void pendingSettingsApplyAtRestart()
    {
        SimShuokeDrive d(driveConfig());
        auto r = d.handle(req(CmdChangeAddress, QByteArray(1, '\x07')), SimShuokeDrive::Medium::Serial, 0);
        QCOMPARE(r->data, QByteArray(1, '\x07'));
        QCOMPARE(r->address, quint8(7)); // the new address answers (the seed's worked example)
        d.handle(req(CmdCanBitrate, QByteArray(1, '\x08')), SimShuokeDrive::Medium::Serial, 0);
        d.handle(req(CmdCanFrameFormat, QByteArray(1, '\x01')), SimShuokeDrive::Medium::Serial, 0);
        QCOMPARE(d.address(), quint8(1));
        QCOMPARE(d.config().canBitrateCode, 12);
        d.powerCycle(10 * DriveMs);
        QCOMPARE(d.address(), quint8(7));
        QCOMPARE(d.config().canBitrateCode, 8);
        QVERIFY(d.config().canExtended);
    }

    void baudAfterPowerUpAndChange()
    {
        SimShuokeDrive::Config c = driveConfig();
        c.baudCode = 8;
        c.powerUpWindowMs = 2000;
        SimShuokeDrive d(c);
        QCOMPARE(d.serialBaud(0), 9600);
        QCOMPARE(d.serialBaud(1999 * DriveMs), 9600);
        QCOMPARE(d.serialBaud(2000 * DriveMs), 38400);
        const auto r = d.handle(req(CmdSetBaudCode, QByteArray(1, '\x05')), SimShuokeDrive::Medium::Serial,
                                3000 * DriveMs);
        QCOMPARE(r->data, QByteArray(1, '\x05'));
        QCOMPARE(d.serialBaud(3001 * DriveMs), 4800);
        d.powerCycle(4000 * DriveMs);
        QCOMPARE(d.serialBaud(4500 * DriveMs), 9600);
        QCOMPARE(d.serialBaud(6000 * DriveMs), 4800);
    }

    void commandsTooSoonAreIgnored()
    {
        SimShuokeDrive::Config c = driveConfig();
        c.minCommandGapMs = 50;
        SimShuokeDrive d(c);
        QVERIFY(d.handle(req(CmdHandshake), SimShuokeDrive::Medium::Serial, 0));
        QVERIFY(!d.handle(req(CmdHandshake), SimShuokeDrive::Medium::Serial, 49 * DriveMs));
        QVERIFY(!d.handle(req(CmdHandshake), SimShuokeDrive::Medium::Plc, 60 * DriveMs)); // 11 ms after the last
        QVERIFY(d.handle(req(CmdHandshake), SimShuokeDrive::Medium::Serial, 110 * DriveMs));
        QVERIFY(d.handle(req(CmdHandshake), SimShuokeDrive::Medium::Can, 111 * DriveMs)); // CAN: no such rule
        QCOMPARE(d.tooSoonCount(), 2);
        QCOMPARE(d.requestCount(), 3);
    }

    void writeOnlyAndReadable()
    {
        SimShuokeDrive d(driveConfig());
        QVERIFY(!d.handle(req(CmdNoEncoderMaxPulses, encodeUInt32(1234)), SimShuokeDrive::Medium::Serial, 0)->failure);
        QCOMPARE(d.setting(CmdNoEncoderMaxPulses), 1234);
        d.handle(req(CmdSetStopSpeed, encodeUInt32(321)), SimShuokeDrive::Medium::Serial, 0);
        QCOMPARE(d.handle(req(CmdGetStopSpeed), SimShuokeDrive::Medium::Serial, 0)->data, encodeUInt32(321));
    }

    void limitsAndHoming()
    {
        SimShuokeDrive::Config c = driveConfig();
        c.switches.leftLimit = -1000;
        c.switches.rightLimit = 1000;
        c.switches.origin = 400;
        SimShuokeDrive d(c);
        d.setSetting(CmdSetHomingSpeed, 10000);
        // negative first: left limit at -1000, reverse, origin at 400
        d.handle(req(CmdHome, QByteArray(1, '\0')), SimShuokeDrive::Medium::Serial, 0);
        qint64 lowest = 0;
        for (qint64 t = 0; t < 2000 * DriveMs && d.axis().isRunning(); t += DriveMs) {
            d.advanceTo(t);
            lowest = std::min(lowest, d.axis().motorPosition());
        }
        QVERIFY(!d.axis().isRunning());
        QVERIFY(lowest <= -1000);
        QVERIFY(!d.axis().homingFailed());
        QVERIFY(std::llabs(d.axis().motorPosition() - 400) <= 10);
        QCOMPARE(d.axis().absolutePosition(), 0);
        QCOMPARE(d.axis().closedLoopAbsolute(), 0);

        // no origin between the limits: the second limit ends the search
        SimShuokeDrive::Config lost = c;
        lost.switches.origin = 5000;
        SimShuokeDrive e(lost);
        e.setSetting(CmdSetHomingSpeed, 10000);
        e.handle(req(CmdHome, QByteArray(1, '\1')), SimShuokeDrive::Medium::Serial, 0);
        e.advanceTo(3000 * DriveMs);
        QVERIFY(!e.axis().isRunning());
        QVERIFY(e.axis().homingFailed());
        QVERIFY(e.axis().leftLimit());

        // a jog into a limit stops there; away from it is allowed
        SimShuokeDrive f(c);
        f.handle(req(CmdRunSpeed, encodeInt32(5000)), SimShuokeDrive::Medium::Serial, 0);
        f.advanceTo(1000 * DriveMs);
        QVERIFY(!f.axis().isRunning());
        QVERIFY(f.axis().rightLimit());
        f.handle(req(CmdRunSpeed, encodeInt32(-5000)), SimShuokeDrive::Medium::Serial, 1000 * DriveMs);
        f.advanceTo(1100 * DriveMs);
        QVERIFY(f.axis().isRunning());
        QVERIFY(!f.axis().rightLimit());
    }

    void noMotionWithoutTheEnableInput()
    {
        // A drive whose ENA input is off has no power stage: it neither runs nor homes, and
        // switching the input off while running lets the shaft coast to rest.
        SimShuokeDrive d(driveConfig());
        d.setEnableInput(false);
        d.handle(req(CmdRunSpeed, encodeInt32(5000)), SimShuokeDrive::Medium::Serial, 0);
        d.advanceTo(200 * DriveMs);
        QVERIFY(!d.axis().isRunning());
        QCOMPARE(d.axis().motorPosition(), 0);
        d.handle(req(CmdHome, QByteArray(1, '\1')), SimShuokeDrive::Medium::Serial, 200 * DriveMs);
        d.advanceTo(400 * DriveMs);
        QVERIFY(!d.axis().isRunning());
        QCOMPARE(d.axis().motorPosition(), 0);

        d.setEnableInput(true);
        d.handle(req(CmdRunSpeed, encodeInt32(5000)), SimShuokeDrive::Medium::Serial, 400 * DriveMs);
        d.advanceTo(600 * DriveMs);
        QVERIFY(d.axis().isRunning());
        d.setEnableInput(false);
        d.advanceTo(3000 * DriveMs);
        QVERIFY(!d.axis().isRunning());
        const qint64 rest = d.axis().motorPosition();
        d.advanceTo(3500 * DriveMs);
        QCOMPARE(d.axis().motorPosition(), rest);
    }

    void stateRoundTrip()
    {
        SimShuokeDrive d(driveConfig(Model::M4505S));
        d.handle(req(CmdSetMaxSpeed, encodeUInt32(4321)), SimShuokeDrive::Medium::Serial, 0);
        d.handle(req(CmdSkipCrcCheck, QByteArray(1, '\1')), SimShuokeDrive::Medium::Serial, 0);
        d.handle(req(CmdSetIoSubstitution, QByteArray::fromHex("030a0b")), SimShuokeDrive::Medium::Serial, 0);
        d.axis().placeAt(777);
        const QJsonObject state = d.saveState();
        SimShuokeDrive e;
        QString error;
        QVERIFY2(e.loadState(state, &error), qPrintable(error));
        QCOMPARE(e.model(), Model::M4505S);
        QCOMPARE(e.setting(CmdSetMaxSpeed), 4321);
        QVERIFY(e.skipsCrcCheck());
        QCOMPARE(e.ioSubstitution(3), QByteArray::fromHex("030a0b"));
        QCOMPARE(e.axis().motorPosition(), 777);
        QCOMPARE(e.axis().absolutePosition(), 0);
        QCOMPARE(e.saveState(), state);
        QJsonObject bad = state;
        bad.insert(QStringLiteral("address"), 300);
        QVERIFY(!e.loadState(bad, &error));
        QVERIFY(error.contains(QStringLiteral("address")));
    }

    void rtuFramingOnTheDriveSide()
    {
        SimShuokeSerialDevice dev(driveConfig());
        const QByteArray get = *encodeRtu(req(CmdGetMaxSpeed)).value;
        // garbage before the frame, the frame split in two chunks
        QList<QByteArray> out = dev.onBusBytes(QByteArray::fromHex("ff00") + get.left(3), 10 * DriveMs);
        QVERIFY(out.isEmpty());
        out = dev.onBusBytes(get.mid(3), 10 * DriveMs + 500);
        QCOMPARE(out.size(), 1);
        QCOMPARE(*decodeRtu(out.first()).value, Frame::make(1, CmdGetMaxSpeed, encodeUInt32(10000)));
        // a bad CRC to this drive: failure 0x02; to another drive: silence
        QByteArray bad = get;
        bad[bad.size() - 1] = static_cast<char>(bad.back() ^ 1);
        out = dev.onBusBytes(bad, 100 * DriveMs);
        QCOMPARE(out.size(), 1);
        QCOMPARE(*decodeRtu(out.first()).value, Frame::failureReply(1, CmdGetMaxSpeed, FailureChecksum));
        QByteArray other = *encodeRtu(req(CmdGetMaxSpeed, {}, 2)).value;
        other[4] = static_cast<char>(other.at(4) ^ 1);
        QVERIFY(dev.onBusBytes(other, 200 * DriveMs).isEmpty());
        // an incomplete frame is forgotten after a silence
        QVERIFY(dev.onBusBytes(get.left(4), 300 * DriveMs).isEmpty());
        QCOMPARE(dev.onBusBytes(get, 400 * DriveMs).size(), 1);
        // M4505S with 0x49 = 1: fixed 10-byte replies
        SimShuokeSerialDevice s(driveConfig(Model::M4505S));
        s.onBusBytes(*encodeRtu(req(CmdFixedLengthReplies, QByteArray(1, '\1'))).value, 0);
        out = s.onBusBytes(*encodeRtu(req(CmdHandshake)).value, 100 * DriveMs);
        QCOMPARE(out.first().size(), kFixedFrameSize);
    }

    void asciiFramingOnTheDriveSide()
    {
        SimShuokeSerialDevice dev(driveConfig(), SimShuokeSerialDevice::Framing::Ascii, AsciiCheck::TwosComplement);
        AsciiOptions o;
        o.check = AsciiCheck::TwosComplement;
        const QByteArray line = *encodeAscii(req(CmdGetStartSpeed), o).value;
        QList<QByteArray> out = dev.onBusBytes("noise" + line, 0);
        QCOMPARE(out.size(), 1);
        QCOMPARE(*decodeAscii(out.first(), o).value, Frame::make(1, CmdGetStartSpeed, encodeUInt32(500)));
        const QByteArray plain = *encodeAscii(req(CmdGetStartSpeed)).value; // the other check byte
        out = dev.onBusBytes(plain, 100 * DriveMs);
        QCOMPARE(*decodeAscii(out.first(), o).value, Frame::failureReply(1, CmdGetStartSpeed, FailureChecksum));
        QCOMPARE(dev.checksumErrors(), quint64(1));
    }

    void plcFramingOnTheDriveSide()
    {
        SimShuokeDrive::Config c = driveConfig();
        c.plcBase = 0x100;
        SimShuokeSerialDevice dev(c, SimShuokeSerialDevice::Framing::Plc);
        PlcOptions o;
        o.base = 0x100;
        const Frame write = req(CmdSetMaxSpeed, encodeUInt32(12345));
        QList<QByteArray> out = dev.onBusBytes(*encodePlcRequest(write, o).value, 0);
        QCOMPARE(out.size(), 1);
        QVERIFY(decodePlcReply(out.first(), write, o).ok());
        QCOMPARE(dev.drive().setting(CmdSetMaxSpeed), 12345);
        const Frame read = req(CmdGetMaxSpeed);
        out = dev.onBusBytes(*encodePlcRequest(read, o).value, 100 * DriveMs);
        QCOMPARE(decodePlcReply(out.first(), read, o).value->data, encodeUInt32(12345));
        // out of range: a Modbus exception carrying the failure code
        const Frame tooFast = req(CmdSetMaxSpeed, encodeUInt32(100001));
        out = dev.onBusBytes(*encodePlcRequest(tooFast, o).value, 200 * DriveMs);
        QCOMPARE(decodePlcReply(out.first(), tooFast, o).value->failureCode, quint8(FailureOutOfRange));
        // a register that maps to no command: exception 0x02
        out = dev.onBusBytes(withCrc16(QByteArray::fromHex("010300000002")), 300 * DriveMs);
        QCOMPARE(out.first().left(3), QByteArray::fromHex("018302"));
        // Shuoke RTU frames still work in PLC mode (0x3F sets the base)
        out = dev.onBusBytes(*encodeRtu(req(CmdSetPlcBase, encodeUInt16(0x200))).value, 400 * DriveMs);
        QCOMPARE(out.size(), 1);
        QCOMPARE(dev.drive().plcBase(), quint16(0x200));
    }
};

QTEST_APPLESS_MAIN(TestSimShuokeDrive)
#include "tst_simshuokedrive.moc"
