#include <QtTest>

#include "core/protocol/shuoke/shuokecan.h"
#include "core/protocol/shuoke/shuokecommands.h"
#include "tests/support/hex.h"
#include "tests/support/shuokeframestring.h"

using namespace dd::shuoke;
using dd::CanFrameData;
using dd::Decoded;

namespace {

using dd::test::hex;
CanFrameData can(quint32 id, const char *h, bool extended = false)
{
    CanFrameData c;
    c.id = id;
    c.data = hex(h);
    c.extended = extended;
    return c;
}
CanFrameData encoded(const Frame &f, const CanOptions &o = {})
{
    const Decoded<CanFrameData> e = encodeCan(f, o);
    return e.ok() ? *e.value : CanFrameData{0xFFFFFFFF, "encode failed", false};
}

} // namespace

class TestShuokeCan : public QObject
{
    Q_OBJECT
private slots:
    // The seed's CAN chapter ("CAN通讯常用指令列表"), with concrete values for its 0xnn.
    void seedExamples_data()
    {
        QTest::addColumn<Frame>("frame");
        QTest::addColumn<int>("id");
        QTest::addColumn<QByteArray>("data");
        auto row = [](const char *name, const Frame &f, const char *h) {
            QTest::newRow(name) << f << int(f.address) << hex(h);
        };
        row("change address 1 -> 2", Frame::make(1, 0x22, hex("02")), "0122010200000000");
        row("change address reply from 2", Frame::make(2, 0x22, hex("02")), "0222010200000000");
        // Seed typo: the "query speed" conversion example shows command 0x21; it is 0x36.
        row("query speed (example 1, address 0)", Frame::make(0, 0x36), "0036000000000000");
        row("set start speed 1000 (example 2)", Frame::make(1, 0x25, hex("e8030000")), "012504e803000000");
        row("CAN -> serial echo 0x4D", Frame::make(1, 0x4D, hex("1122334455")), "014d051122334455");
        row("serial -> CAN echo 0x4C", Frame::make(1, 0x4C, hex("a1a2a3a4a5")), "014c05a1a2a3a4a5");
        row("query address, broadcast", Frame::make(0, 0x21), "0021000000000000");
        row("handshake", Frame::make(1, 0x20), "0120000000000000");
        row("change address", Frame::make(1, 0x22, hex("02")), "0122010200000000");
        row("get baud", Frame::make(1, 0x23), "0123000000000000");
        row("set baud 9600", Frame::make(1, 0x24, hex("06")), "0124010600000000");
        row("set start speed", Frame::make(1, 0x25, hex("10270000")), "0125041027000000");
        row("get start speed", Frame::make(1, 0x26), "0126000000000000");
        row("set max speed", Frame::make(1, 0x27, hex("a0860100")), "012704a086010000");
        row("get max speed", Frame::make(1, 0x28), "0128000000000000");
        row("set stop speed", Frame::make(1, 0x29, hex("64000000")), "0129046400000000");
        row("get stop speed", Frame::make(1, 0x2A), "012a000000000000");
        row("set acceleration", Frame::make(1, 0x2B, hex("88130000")), "012b048813000000");
        row("get acceleration", Frame::make(1, 0x2C), "012c000000000000");
        row("set deceleration", Frame::make(1, 0x2D, hex("88130000")), "012d048813000000");
        row("get deceleration", Frame::make(1, 0x2E), "012e000000000000");
        row("set homing speed", Frame::make(1, 0x2F, hex("e8030000")), "012f04e803000000");
        row("get homing speed", Frame::make(1, 0x30), "0130000000000000");
        row("move 1 (signed)", Frame::make(1, 0x31, hex("18fcffff")), "01310418fcffff00");
        row("move 2 (direction + pulses)", Frame::make(1, 0x32, hex("01400d03")),
            "013204"
            "01400d0300");
        row("jog 1 (signed)", Frame::make(1, 0x33, hex("e8030000")), "013304e803000000");
        row("jog 2 (direction + speed)", Frame::make(1, 0x34, hex("00e80300")), "01340400e8030000");
        row("change speed", Frame::make(1, 0x35, hex("d0070000")), "013504d007000000");
        // The seed shows "0x3E 0x01 0xnn 0xnn 0xnn 0xnn": len 1, so one byte + padding.
        row("home", Frame::make(1, 0x3E, hex("01")), "013e010100000000");
        row("emergency stop", Frame::make(1, 0x3C), "013c000000000000");
        row("decelerate to stop", Frame::make(1, 0x3D), "013d000000000000");
        row("query speed", Frame::make(1, 0x36), "0136000000000000");
        row("query absolute position", Frame::make(1, 0x37), "0137000000000000");
        row("clear absolute position", Frame::make(1, 0x38), "0138000000000000");
        row("query relative position", Frame::make(1, 0x39), "0139000000000000");
        row("clear relative position", Frame::make(1, 0x3A), "013a000000000000");
        row("query status", Frame::make(1, 0x3B), "013b000000000000");
        row("inputs IN1..5", Frame::make(1, 0x42), "0142000000000000");
        row("closed loop move", Frame::make(1, 0x55, hex("40420f00")), "01550440420f0000");
        row("closed loop geared move", Frame::make(1, 0x56, hex("c0bdf0ff")), "015604c0bdf0ff00");
        row("closed loop absolute move", Frame::make(1, 0x57, hex("00000100")), "0157040000010000");
        row("read closed-loop absolute", Frame::make(1, 0x58), "0158000000000000");
        row("clear closed-loop absolute", Frame::make(1, 0x59), "0159000000000000");
        row("set closed-loop absolute", Frame::make(1, 0x59, hex("0a000000")), "0159040a00000000");
        row("read closed-loop relative", Frame::make(1, 0x5A), "015a000000000000");
        row("clear closed-loop relative", Frame::make(1, 0x5B), "015b000000000000");
        row("set closed-loop relative", Frame::make(1, 0x5B, hex("f6ffffff")), "015b04f6ffffff00");
        row("encoder direction", Frame::make(1, 0x5C, hex("01")), "015c010100000000");
        row("motion direction", Frame::make(1, 0x5D, hex("00")), "015d010000000000");
        row("error correction", Frame::make(1, 0x5E, hex("01")), "015e010100000000");
        row("set gear numerator", Frame::make(1, 0x5F, hex("10000000")), "015f041000000000");
        row("get gear numerator", Frame::make(1, 0x60), "0160000000000000");
        row("set gear denominator", Frame::make(1, 0x61, hex("03000000")), "0161040300000000");
        row("get gear denominator", Frame::make(1, 0x62), "0162000000000000");
        row("A/B tolerance 200", Frame::make(1, 0x65, hex("c8000000")), "016504c800000000");
        row("no-encoder pulses 5000", Frame::make(1, 0x66, hex("88130000")), "0166048813000000");
        for (quint8 code = 1; code <= 5; ++code) {
            static const char *wires[] = {"01b6010100000000", "01b6010200000000", "01b6010300000000",
                                          "01b6010400000000", "01b6010500000000"};
            QTest::addRow("failure code %d", code) << Frame::failureReply(1, 0x36, code) << 1 << hex(wires[code - 1]);
        }
    }
    void seedExamples()
    {
        QFETCH(Frame, frame);
        QFETCH(int, id);
        QFETCH(QByteArray, data);
        const CanFrameData c = encoded(frame);
        QCOMPARE(int(c.id), id);
        QVERIFY(!c.extended);
        QCOMPARE(c.data.toHex(' '), data.toHex(' '));
        const Decoded<Frame> d = decodeCan(c);
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(*d.value, frame);
    }

    void extendedFrames()
    {
        const Frame f = Frame::make(5, 0x36);
        CanOptions o;
        o.extended = true;
        QCOMPARE(encoded(f, o), can(5, "0536000000000000", true)); // default: extended id = address
        o.extendedId = CanExtendedId::Zero;
        QCOMPARE(encoded(f, o), can(0, "0536000000000000", true));
        QCOMPARE(*decodeCan(can(5, "0536000000000000", true)).value, f);
        QCOMPARE(*decodeCan(can(0, "0536000000000000", true)).value, f);
        QVERIFY(!decodeCan(can(6, "0536000000000000", true)).ok());
        // extendedId only matters for extended frames
        QCOMPARE(encoded(f, o), can(0, "0536000000000000", true));
        o.extended = false;
        QCOMPARE(encoded(f, o), can(5, "0536000000000000"));
    }

    void refusesWhatDoesNotFit()
    {
        const Decoded<CanFrameData> e = encodeCan(Frame::make(1, 0x40, hex("03112233445566")));
        QVERIFY(!e.ok());
        QVERIFY2(e.error.contains(QLatin1String("does not fit")), qPrintable(e.error));
        QVERIFY(!encodeCan(Frame::make(1, 0x40, hex("031122334455"))).ok());
        QVERIFY(encodeCan(Frame::make(1, 0x40, hex("0311223344"))).ok());
        QVERIFY(!encodeCan(Frame::make(1, 0x41, hex("01112233445566"))).ok()); // a 7-byte 0x41 reply
    }

    void roundTripEveryCommand()
    {
        int checked = 0;
        int seed = 0;
        for (const CommandInfo &c : commandTable()) {
            QList<Frame> frames;
            auto add = [&](quint8 command, int n) {
                const int s = seed++;
                frames.append(Frame::make(static_cast<quint8>(1 + s % 250), command, QByteArray(n, char(0x40 + s))));
            };
            for (int n = 0; n <= kCanMaxData; ++n) {
                if (c.allowsRequestLength(n))
                    add(c.code, n);
                for (const quint8 reply : c.replyCommands)
                    if (reply && c.allowsReplyLength(n))
                        add(reply, n);
            }
            const int s = seed++;
            frames.append(
                Frame::failureReply(static_cast<quint8>(1 + s % 250), c.code, static_cast<quint8>(1 + s % 5)));
            for (const Frame &f : frames) {
                for (const bool extended : {false, true}) {
                    CanOptions o;
                    o.extended = extended;
                    const CanFrameData e = encoded(f, o);
                    QCOMPARE(e.data.size(), kCanFrameBytes);
                    QCOMPARE(e.id, quint32(f.address));
                    QCOMPARE(e.extended, extended);
                    QCOMPARE(*decodeCan(e).value, f);
                    ++checked;
                }
            }
        }
        QVERIFY(checked > 200);
    }

    void decodeTolerance()
    {
        // DLC below 8 still holding the frame
        QCOMPARE(*decodeCan(can(1, "01360400000100")).value, Frame::make(1, 0x36, hex("00000100")));
        QCOMPARE(*decodeCan(can(1, "013800")).value, Frame::make(1, 0x38));
        // padding is not checked
        QCOMPARE(*decodeCan(can(1, "013800ffffffffff")).value, Frame::make(1, 0x38));
        // broadcast id 0
        QCOMPARE(*decodeCan(can(0, "0021000000000000")).value, Frame::make(0, 0x21));
    }

    void malformed_data()
    {
        QTest::addColumn<CanFrameData>("frame");
        QTest::addColumn<QString>("why");
        QTest::newRow("empty") << can(1, "") << "too short";
        QTest::newRow("2 bytes") << can(1, "0136") << "too short";
        QTest::newRow("9 bytes") << can(1, "013600000000000000") << "at most 8";
        QTest::newRow("id differs from address") << can(2, "0136000000000000") << "does not match";
        QTest::newRow("len 6") << can(1, "0136060000000000") << "length byte";
        QTest::newRow("len beyond DLC") << can(1, "013604000000") << "length byte";
        QTest::newRow("failure len 0") << can(1, "01b6000000000000") << "failure";
        QTest::newRow("failure len 2") << can(1, "01b6020400000000") << "failure";
        QTest::newRow("extended id neither") << can(7, "0136000000000000", true) << "neither";
    }
    void malformed()
    {
        QFETCH(CanFrameData, frame);
        QFETCH(QString, why);
        const Decoded<Frame> d = decodeCan(frame);
        QVERIFY(!d.ok());
        QVERIFY2(d.error.contains(why), qPrintable(d.error));
    }
};

QTEST_APPLESS_MAIN(TestShuokeCan)
#include "tst_shuokecan.moc"
