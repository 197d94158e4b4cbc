// The simulated Shuoke drive against the seed (docs/protocols/shuoke.md), where it was not:
// 0x36 reports the speed's magnitude ("4BYTE 运动速度"; only 0x37 is signed), and the gear
// numerator / denominator (0x5F / 0x61) keep the low 16 bits of a larger value
// ("大于16位，只取16无符号位数") instead of refusing it.
#include <QtTest>

#include "core/protocol/shuoke/shuokevalues.h"
#include "sim/shuoke/simshuokedrive.h"

using namespace dd;
using namespace dd::shuoke;

namespace {
constexpr qint64 Ms = 1000;

SimShuokeDrive::Config config()
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
        SimShuokeDrive d(config());
        QVERIFY(ask(d, CmdRunSpeed, encodeInt32(speed), 0).command == CmdRunSpeed);
        const Frame f = ask(d, CmdQuerySpeed, {}, 2000 * Ms); // at speed by now
        QVERIFY(!f.failure);
        QCOMPARE(f.data, encodeUInt32(1000)); // E8 03 00 00 both ways
        // The position (0x37) keeps its sign.
        const Frame p = ask(d, CmdQueryAbsolutePosition, {}, 2000 * Ms);
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
        SimShuokeDrive d(config());
        const Frame ack = ask(d, quint8(set), encodeUInt32(value), 0);
        QVERIFY2(!ack.failure, "the drive takes it (no error 4)");
        QCOMPARE(ask(d, quint8(get), {}, 0).data, encodeUInt32(kept));
    }

    // A denominator whose low 16 bits are 0 is still refused (error 4): 0 is no divisor.
    void gearDenominatorWithZeroLowBitsIsRefused()
    {
        SimShuokeDrive d(config());
        const Frame f = ask(d, CmdSetGearDenominator, encodeUInt32(0x10000), 0);
        QVERIFY(f.failure);
        QCOMPARE(int(f.failureCode), 4);
        QCOMPARE(ask(d, CmdGetGearDenominator, {}, 0).data, encodeUInt32(1));
    }
};

QTEST_GUILESS_MAIN(TestSimShuokeSeeds)
#include "tst_simshuokeseeds.moc"
