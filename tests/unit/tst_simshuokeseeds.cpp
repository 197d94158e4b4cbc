// The simulated Shuoke drive against the seed (docs/protocols/shuoke.md, "Simulator
// conformance"), where it was not:
// - 0x36 reports the speed's magnitude ("4BYTE 运动速度"; only 0x37 is signed), and the gear
//   numerator / denominator (0x5F / 0x61) keep the low 16 bits of a larger value
//   ("大于16位，只取16无符号位数") instead of refusing it;
// - the systematic pass: speeds above 65535 kept whole, 0x22 answered from the new address,
//   the reply codes the seed prints (0x41, 0x3E), the homing variants 0x4E / 0x4F, 0x45 /
//   0x46 only during motion, 31-bit results of 0x56, padded (fixed-length) requests, the CAN
//   filter (DLC 8, no broadcast at 255).
// Wire bytes are written by hand from the seed (CRC-16/MODBUS computed once, outside the code
// under test); values in place of the seed's 0xnn are ours.
#include <QtTest>

#include "core/protocol/canframedata.h"
#include "core/protocol/shuoke/shuokevalues.h"
#include "sim/shuoke/simshuokecandevice.h"
#include "sim/shuoke/simshuokedrive.h"
#include "sim/shuoke/simshuokeserialdevice.h"

using namespace dd;
using namespace dd::shuoke;

namespace {
constexpr qint64 SeedMs = 1000;

SimShuokeDrive::Config seedConfig()
{
    SimShuokeDrive::Config c;
    c.model = Model::M6505;
    c.powerUpWindowMs = 0;
    c.minCommandGapMs = 0;
    return c;
}

Frame ask(SimShuokeDrive &d, quint8 cmd, const QByteArray &data, qint64 atUs)
{
    const std::optional<Frame> f = d.handle(Frame::make(1, cmd, data), SimShuokeDrive::Medium::Serial, atUs);
    return f ? *f : Frame{};
}

// What the drive sends back on RS485 for the bytes `seedHex` arriving at `atUs`.
QByteArray wire(SimShuokeSerialDevice &dev, const char *seedHex, qint64 atUs)
{
    QByteArray out;
    for (const QByteArray &frame : dev.onBusBytes(QByteArray::fromHex(seedHex), atUs))
        out += frame;
    return out;
}

QByteArray seedHex(const char *text)
{
    return QByteArray::fromHex(text);
}

// The data bytes of the reply to CAN frame `data` sent with identifier `id`; "none" if silent.
QByteArray can(SimShuokeCanDevice &dev, quint32 id, const char *data, qint64 atUs = 0)
{
    CanFrameData f;
    f.id = id;
    f.data = QByteArray::fromHex(data);
    const QList<CanFrameData> out = dev.onCanFrame(f, atUs);
    if (out.isEmpty())
        return "none";
    return QByteArray::number(out.first().id, 16) + ':' + out.first().data.toHex(' ');
}
} // namespace

class TestSimShuokeSeeds : public QObject
{
    Q_OBJECT
private slots:
    void speedIsReportedAsItsMagnitude_data()
    {
        QTest::addColumn<int>("speed");
        QTest::newRow("forwards") << 1000;
        QTest::newRow("backwards") << -1000;
    }
    void speedIsReportedAsItsMagnitude()
    {
        QFETCH(int, speed);
        SimShuokeDrive d(seedConfig());
        QVERIFY(ask(d, CmdRunSpeed, encodeInt32(speed), 0).command == CmdRunSpeed);
        const Frame f = ask(d, CmdQuerySpeed, {}, 2000 * SeedMs); // at speed by now
        QVERIFY(!f.failure);
        QCOMPARE(f.data, encodeUInt32(1000)); // E8 03 00 00 both ways
        // The position (0x37) keeps its sign.
        const Frame p = ask(d, CmdQueryAbsolutePosition, {}, 2000 * SeedMs);
        QVERIFY(speed < 0 ? qint32(*decodeUInt32(p.data)) < 0 : qint32(*decodeUInt32(p.data)) > 0);
    }

    void gearKeepsTheLow16Bits_data()
    {
        QTest::addColumn<int>("set");
        QTest::addColumn<int>("get");
        QTest::addColumn<quint32>("value");
        QTest::addColumn<quint32>("kept");
        QTest::newRow("numerator 0x12345")
            << int(CmdSetGearNumerator) << int(CmdGetGearNumerator) << 0x12345u << 0x2345u;
        QTest::newRow("denominator 0x1FFFF")
            << int(CmdSetGearDenominator) << int(CmdGetGearDenominator) << 0x1FFFFu << 0xFFFFu;
        QTest::newRow("numerator 0xFFFF") << int(CmdSetGearNumerator) << int(CmdGetGearNumerator) << 0xFFFFu << 0xFFFFu;
    }
    void gearKeepsTheLow16Bits()
    {
        QFETCH(int, set);
        QFETCH(int, get);
        QFETCH(quint32, value);
        QFETCH(quint32, kept);
        SimShuokeDrive d(seedConfig());
        const Frame ack = ask(d, quint8(set), encodeUInt32(value), 0);
        QVERIFY2(!ack.failure, "the drive takes it (no error 4)");
        QCOMPARE(ask(d, quint8(get), {}, 0).data, encodeUInt32(kept));
    }

    // A denominator whose low 16 bits are 0 is still refused (error 4): 0 is no divisor.
    void gearDenominatorWithZeroLowBitsIsRefused()
    {
        SimShuokeDrive d(seedConfig());
        const Frame f = ask(d, CmdSetGearDenominator, encodeUInt32(0x10000), 0);
        QVERIFY(f.failure);
        QCOMPARE(int(f.failureCode), 4);
        QCOMPARE(ask(d, CmdGetGearDenominator, {}, 0).data, encodeUInt32(1));
    }

    // 0x27 / 0x28 "数据范围：0----100K": 100000 is kept whole (it was cut to its low 16 bits,
    // 0x86A0 = 34464, along with the gear values).
    void speedsAbove65535AreKeptWhole()
    {
        SimShuokeSerialDevice dev(seedConfig());
        QCOMPARE(wire(dev, "01 27 04 A0 86 01 00 3E AE", 0), seedHex("01 27 00 3B F0"));
        QCOMPARE(wire(dev, "01 28 00 3E 00", 100 * SeedMs), seedHex("01 28 04 A0 86 01 00 3E 51"));
    }

    // The worked example of the ASCII and CAN chapters: 发送 01 22 01 02, 应答 02 22 01 02 —
    // the reply comes from the new address; the drive answers the old one until it restarts.
    void changeAddressIsAnsweredFromTheNewAddress()
    {
        SimShuokeSerialDevice dev(seedConfig());
        QCOMPARE(wire(dev, "01 22 01 02 21 83", 0), seedHex("02 22 01 02 21 C7"));
        QCOMPARE(wire(dev, "01 20 00 39 C0", 100 * SeedMs), seedHex("01 20 00 39 C0"));
        dev.powerCycle();
        QCOMPARE(wire(dev, "02 20 00 C9 C0", 200 * SeedMs), seedHex("02 20 00 C9 C0"));
    }

    // The seed prints reply command 0x41 for 0x42 and 0x43 (and 0x44..0x46).
    void inputQueriesAnswerWithTheCommandTheSeedPrints()
    {
        SimShuokeSerialDevice dev(seedConfig());
        QCOMPARE(wire(dev, "01 42 00 10 A0", 0), seedHex("01 41 05 00 00 00 00 00 D0 96"));
        // 0x43: 脉冲pu/方向dr/使能en/f1/f2; the enable input is on.
        QCOMPARE(wire(dev, "01 43 00 11 30", 100 * SeedMs), seedHex("01 41 05 00 00 01 00 00 81 56"));
    }

    // 自动查找原点命令3 (0x4F, one byte): answered 0x3E, like command 1 but without
    // "自动将相对位置和绝对位置清零": the counters keep counting.
    void homingVariant3KeepsTheCounters()
    {
        SimShuokeSerialDevice dev(seedConfig());
        dev.drive().axis().placeAt(-5000); // counters zeroed 5000 pulses before the origin
        QCOMPARE(wire(dev, "01 4F 01 01 F0 5F", 0), seedHex("01 3E 00 30 60"));
        dev.advanceTo(5000 * SeedMs);
        QVERIFY(!dev.drive().axis().isRunning());
        QVERIFY(dev.drive().axis().origin());
        QCOMPARE(wire(dev, "01 37 00 36 30", 5000 * SeedMs), seedHex("01 37 04 88 13 00 00 24 22")); // 5000
    }

    // 自动查找原点命令2 (0x4E, one byte): "先到限位，然后反方向查找" — to the limit first, then
    // back to the origin, zeroing the counters; answered 0x3E.
    void homingVariant2GoesToTheLimitFirst()
    {
        SimShuokeDrive::Config c = seedConfig();
        c.switches.rightLimit = 20000;
        SimShuokeSerialDevice dev(c);
        dev.drive().axis().placeAt(-5000);
        QCOMPARE(wire(dev, "01 4E 01 01 A1 9F", 0), seedHex("01 3E 00 30 60"));
        dev.advanceTo(3000 * SeedMs); // 0x3E would have stopped at the origin after ~1 s
        QVERIFY(dev.drive().axis().isRunning());
        QVERIFY(dev.drive().axis().motorPosition() > 5000);
        dev.advanceTo(15000 * SeedMs);
        QVERIFY(!dev.drive().axis().isRunning());
        QVERIFY(!dev.drive().axis().homingFailed());
        QVERIFY(dev.drive().axis().origin());
        QCOMPARE(wire(dev, "01 37 00 36 30", 15000 * SeedMs), seedHex("01 37 04 00 00 00 00 FE 47"));
    }

    // 0x45 "运动中定量改变速度（加）": 运动速度 = 当前运动速度 + F during a move keeps the move's
    // target (it used to turn the move into an endless jog); at rest nothing starts.
    void speedStepKeepsAMoveAndStartsNothingAtRest()
    {
        SimShuokeDrive::Config c = seedConfig();
        c.model = Model::M4505S;
        SimShuokeSerialDevice dev(c);
        QCOMPARE(wire(dev, "01 45 00 12 90", 0), seedHex("01 41 00 10 50"));
        dev.advanceTo(1000 * SeedMs);
        QVERIFY(!dev.drive().axis().isRunning());
        QCOMPARE(wire(dev, "01 44 04 E8 03 00 00 30 E4", 1000 * SeedMs), seedHex("01 41 00 10 50")); // F = 1000
        QCOMPARE(wire(dev, "01 31 04 20 4E 00 00 95 F6", 1100 * SeedMs), seedHex("01 31 00 35 90")); // +20000
        QCOMPARE(wire(dev, "01 45 00 12 90", 1600 * SeedMs), seedHex("01 41 00 10 50"));
        QCOMPARE(dev.drive().axis().motor().moveSpeed(), 11000.0); // 10000 + F
        dev.advanceTo(10000 * SeedMs);
        QVERIFY(!dev.drive().axis().isRunning());
        QCOMPARE(wire(dev, "01 37 00 36 30", 10000 * SeedMs), seedHex("01 37 04 20 4E 00 00 95 90"));
    }

    // 0x56: "最高支持数据为运算后的实际反馈脉冲数为31位": 0x10000 x 65535 / 1 is beyond 31 bits:
    // error 0x04, no motion.
    void gearedMoveBeyond31BitsIsOutOfRange()
    {
        SimShuokeSerialDevice dev(seedConfig());
        QCOMPARE(wire(dev, "01 5F 04 FF FF 00 00 F6 8B", 0), seedHex("01 5F 00 19 F0"));
        QCOMPARE(wire(dev, "01 56 04 00 00 01 00 F7 A6", 100 * SeedMs), seedHex("01 D6 01 04 E0 73"));
        QVERIFY(!dev.drive().axis().isRunning());
    }

    // 0x49: "驱动器接受命令同时支持这两种格式" — a request in the fixed 8-byte layout (data
    // zero-padded to 5, CRC over the 8) is taken (it drew a checksum error 0x02).
    void paddedRequestIsTaken()
    {
        SimShuokeSerialDevice dev(seedConfig());
        QCOMPARE(wire(dev, "01 28 00 00 00 00 00 00 29 C5", 0), seedHex("01 28 04 10 27 00 00 48 E3"));
        QCOMPARE(dev.checksumErrors(), quint64(0));
        // A short frame with a bad CRC is still a checksum error.
        QCOMPARE(wire(dev, "01 28 00 3E 01", 100 * SeedMs), seedHex("01 A8 01 02 00 69"));
    }

    // The CAN filter: "CAN的数据长度 = 8"; identifiers 251..255 reserved, 0 the broadcast.
    void canFilterTakesEightByteFramesAndBroadcastZeroOnly()
    {
        SimShuokeCanDevice dev(seedConfig());
        QCOMPARE(can(dev, 0x001, "01 28 00 00 00 00 00 00"), QByteArray("1:01 28 04 10 27 00 00 00"));
        QCOMPARE(can(dev, 0x001, "01 28 00"), QByteArray("none"));
        QCOMPARE(can(dev, 0x000, "00 21 00 00 00 00 00 00"), QByteArray("1:01 21 00 00 00 00 00 00"));
        QCOMPARE(can(dev, 0x0FF, "FF 21 00 00 00 00 00 00"), QByteArray("none"));
    }
};

QTEST_GUILESS_MAIN(TestSimShuokeSeeds)
#include "tst_simshuokeseeds.moc"
