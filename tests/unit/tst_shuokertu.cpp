#include <QtTest>

#include "core/protocol/modbus/crc16.h"
#include "core/protocol/shuoke/shuokecommands.h"
#include "core/protocol/shuoke/shuokertu.h"
#include "core/protocol/shuoke/shuokertustreamparser.h"
#include "tests/support/hex.h"
#include "tests/support/shuokeframestring.h"

using namespace dd::shuoke;
using dd::Decoded;

namespace {

using dd::test::hex;
QByteArray rtuData(int n, int seed) // distinct, non-trivial bytes
{
    QByteArray d;
    for (int i = 0; i < n; ++i)
        d.append(static_cast<char>(0x11 * (i + 1) + seed));
    return d;
}
QByteArray rtuBytes(const Frame &f, const RtuOptions &o = {})
{
    const auto e = encodeRtu(f, o);
    return e.ok() ? *e.value : QByteArray("encode failed");
}

// Every request and every success reply of the table, and a failure reply per command.
QList<Frame> everyRtuFrame()
{
    QList<Frame> out;
    int seed = 0;
    for (const CommandInfo &c : commandTable()) {
        for (int n = 0; n < 16; ++n)
            if (c.allowsRequestLength(n))
                out.append(Frame::make(7, c.code, rtuData(n, seed++)));
        for (const quint8 reply : c.replyCommands) {
            if (reply == 0)
                continue;
            for (int n = 0; n < 16; ++n)
                if (c.allowsReplyLength(n))
                    out.append(Frame::make(7, reply, rtuData(n, seed++)));
        }
        out.append(Frame::failureReply(7, c.code, static_cast<quint8>(1 + seed++ % 5)));
    }
    return out;
}

struct Lcg
{
    quint32 state;
    quint8 next()
    {
        state = state * 1103515245u + 12345u;
        return static_cast<quint8>(state >> 16);
    }
};

} // namespace

class TestShuokeRtu : public QObject
{
    Q_OBJECT
private slots:
    // Worked examples of the seed (its CRCs are "0xnn": computed independently here).
    void seedExamples_data()
    {
        QTest::addColumn<Frame>("frame");
        QTest::addColumn<QByteArray>("wire");
        QTest::newRow("handshake") << Frame::make(1, 0x20) << hex("01200039c0");
        QTest::newRow("query address, broadcast 0") << Frame::make(0, 0x21) << hex("0021006990");
        QTest::newRow("query address reply") << Frame::make(1, 0x21) << hex("0121003850");
        QTest::newRow("change address 1 -> 2") << Frame::make(1, 0x22, hex("02"))
                                               << hex("0122010221"
                                                      "83");
        QTest::newRow("change address reply from new") << Frame::make(2, 0x22, hex("02"))
                                                       << hex("02220102"
                                                              "21c7");
        QTest::newRow("get baud") << Frame::make(1, 0x23) << hex("0123003930");
        QTest::newRow("get baud reply 9600") << Frame::make(1, 0x23, hex("06"))
                                             << hex("0123010671"
                                                    "80");
        QTest::newRow("set baud 9600") << Frame::make(1, 0x24, hex("06")) << hex("01240106c041");
        QTest::newRow("set start speed 1000") << Frame::make(1, 0x25, hex("e8030000")) << hex("012504e80300003895");
        QTest::newRow("set start speed reply") << Frame::make(1, 0x25) << hex("0125003a90");
        QTest::newRow("query speed") << Frame::make(1, 0x36) << hex("01360037a0");
        QTest::newRow("query speed reply 100000") << Frame::make(1, 0x36, hex("a0860100")) << hex("013604a08601003def");
        QTest::newRow("absolute position -1000") << Frame::make(1, 0x37, hex("18fcffff")) << hex("01370418fcffff3967");
        QTest::newRow("query status") << Frame::make(1, 0x3B) << hex("013b003330");
        QTest::newRow("status reply") << Frame::make(1, 0x3B, hex("0100010001")) << hex("013b050100010001a691");
        QTest::newRow("inputs IO1..5") << Frame::make(1, 0x42) << hex("01420010a0");
        QTest::newRow("inputs reply as 0x41") << Frame::make(1, 0x41, hex("0101000001")) << hex("01410501010000012d6a");
        QTest::newRow("homing variant 2") << Frame::make(1, 0x4E, hex("01")) << hex("014e0101a19f");
        QTest::newRow("homing reply as 0x3E") << Frame::make(1, 0x3E) << hex("013e003060");
        QTest::newRow("move dir24 +200000") << Frame::make(1, 0x32, hex("01400d03")) << hex("01320401400d03baab");
        QTest::newRow("jog dir24 -1000") << Frame::make(1, 0x34, hex("00e80300")) << hex("01340400e803007eb0");
        QTest::newRow("IO substitution, 7 bytes") << Frame::make(1, 0x40, hex("03112233445566"))
                                                  << hex("014007031122334455666"
                                                         "98a");
        for (quint8 code = 1; code <= 5; ++code) {
            static const char *wires[] = {"01a50101d1ab", "01a5010291aa", "01a50103506a", "01a5010411a8",
                                          "01a50105d068"};
            QTest::addRow("failure code %d", code) << Frame::failureReply(1, 0x25, code) << hex(wires[code - 1]);
        }
        QTest::newRow("failure of unknown command") << Frame::failureReply(1, 0x67, 3) << hex("01e70103f07e");
    }
    void seedExamples()
    {
        QFETCH(Frame, frame);
        QFETCH(QByteArray, wire);
        QCOMPARE(rtuBytes(frame).toHex(' '), wire.toHex(' '));
        RtuLayout layout = RtuLayout::FixedLength;
        const Decoded<Frame> d = decodeRtu(wire, {}, &layout);
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(*d.value, frame);
        QCOMPARE(layout, RtuLayout::Standard);
    }

    void failureFrameFields()
    {
        const Frame f = *decodeRtu(hex("01a5010411a8")).value;
        QVERIFY(f.failure);
        QCOMPARE(f.command, quint8(0x25));
        QCOMPARE(f.failureCode, quint8(FailureOutOfRange));
        QVERIFY(f.data.isEmpty());
        QCOMPARE(f.commandByte(), quint8(0xA5));
        // rtuData of a failure Frame is not sent: the code is
        Frame g = Frame::failureReply(1, 0xA5, 4);
        g.data = hex("99");
        QCOMPARE(rtuBytes(g).toHex(), QByteArray("01a5010411a8"));
    }

    void roundTripEveryCommand()
    {
        for (const Frame &f : everyRtuFrame()) {
            for (const bool padded : {false, true}) {
                RtuOptions o;
                o.padToFixedLength = padded;
                const QByteArray wire = rtuBytes(f, o);
                const int n = static_cast<int>(f.payload().size());
                QCOMPARE(wire.size(), padded && n < kFixedDataSize ? kFixedFrameSize : n + kRtuOverhead);
                RtuLayout layout;
                const Decoded<Frame> d = decodeRtu(wire, {}, &layout);
                QVERIFY2(d.ok(), qPrintable(d.error + " " + wire.toHex(' ')));
                QCOMPARE(*d.value, f);
                QCOMPARE(layout, padded && n < kFixedDataSize ? RtuLayout::FixedLength : RtuLayout::Standard);
            }
        }
    }

    void encodeTooLong()
    {
        QVERIFY(!encodeRtu(Frame::make(1, 0x40, QByteArray(256, 'x'))).ok());
        QVERIFY(encodeRtu(Frame::make(1, 0x40, QByteArray(255, 'x'))).ok());
    }

    // Decision (docs/protocols/shuoke.md): len may count the two CRC bytes, accepted when the CRC checks.
    void lengthCountsCrc_data()
    {
        QTest::addColumn<QByteArray>("wire");
        QTest::addColumn<Frame>("frame");
        QTest::newRow("speed reply") << hex("013606a0860100442f") << Frame::make(1, 0x36, hex("a0860100"));
        QTest::newRow("empty reply") << hex("012502bb51") << Frame::make(1, 0x25);
        QTest::newRow("failure") << hex("01a5030410c8") << Frame::failureReply(1, 0x25, 4);
    }
    void lengthCountsCrc()
    {
        QFETCH(QByteArray, wire);
        QFETCH(Frame, frame);
        RtuLayout layout;
        const Decoded<Frame> d = decodeRtu(wire, {}, &layout);
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(*d.value, frame);
        QCOMPARE(layout, RtuLayout::LengthCountsCrc);
        RtuOptions strict;
        strict.acceptLengthWithCrc = false;
        QVERIFY(!decodeRtu(wire, strict).ok());
    }
    void lengthCountsCrcNeedsKnownLayout()
    {
        // 0x3B with len 5 counting the CRC would carry 3 rtuData bytes: no command does that.
        const QByteArray wire = withCrcOf(hex("013b05010001"));
        QVERIFY(!decodeRtu(wire).ok());
        // A CRC-correct frame whose len fits no reading.
        const Decoded<Frame> d = decodeRtu(withCrcOf(hex("01360901")));
        QVERIFY(!d.ok());
        QVERIFY2(d.error.contains(QLatin1String("length byte")), qPrintable(d.error));
    }

    // 0x49 (M4505S): fixed 10-byte frames, rtuData zero-padded to 5 bytes.
    void fixedLength_data()
    {
        QTest::addColumn<QByteArray>("wire");
        QTest::addColumn<Frame>("frame");
        QTest::newRow("clear reply") << hex("01380000000000003804") << Frame::make(1, 0x38);
        QTest::newRow("speed reply") << hex("013604a0860100002ed1") << Frame::make(1, 0x36, hex("a0860100"));
        QTest::newRow("failure") << hex("01a50104000000"
                                        "0084dc")
                                 << Frame::failureReply(1, 0x25, 4);
    }
    void fixedLength()
    {
        QFETCH(QByteArray, wire);
        QFETCH(Frame, frame);
        RtuOptions pad;
        pad.padToFixedLength = true;
        QCOMPARE(rtuBytes(frame, pad).toHex(' '), wire.toHex(' '));
        RtuLayout layout;
        const Decoded<Frame> d = decodeRtu(wire, {}, &layout);
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(*d.value, frame);
        QCOMPARE(layout, RtuLayout::FixedLength);
        RtuOptions strict;
        strict.acceptFixedLength = false;
        QVERIFY(!decodeRtu(wire, strict).ok());
        // A 5-byte status reply is the same in both layouts.
        QCOMPARE(rtuBytes(Frame::make(1, 0x3B, hex("0100010001")), pad).toHex(), QByteArray("013b050100010001a691"));
    }

    void handshakeWithoutCrc()
    {
        const QByteArray wire = hex("0120000000");
        QVERIFY(!decodeRtu(wire).ok());
        RtuOptions drive;
        drive.skipHandshakeCrc = true;
        QCOMPARE(*decodeRtu(wire, drive).value, Frame::make(1, 0x20));
        QVERIFY(!decodeRtu(hex("0136000000"), drive).ok()); // only the handshake
    }

    void malformed_data()
    {
        QTest::addColumn<QByteArray>("wire");
        QTest::addColumn<QString>("why");
        QTest::newRow("empty") << QByteArray() << "too short";
        QTest::newRow("4 bytes") << hex("01200039") << "too short";
        QTest::newRow("truncated") << hex("012504e8030000") << "length byte";
        QTest::newRow("extra byte") << hex("01200039c000") << "length byte";
        QTest::newRow("bad crc") << hex("01200039c1") << "CRC";
        QTest::newRow("crc swapped") << hex("012000c039") << "CRC";
        QTest::newRow("len too big") << hex("01200439c0") << "length byte";
        QTest::newRow("failure, 2 rtuData bytes") << withCrcOf(hex("01a5020400")) << "failure reply";
        QTest::newRow("failure, no rtuData") << withCrcOf(hex("01a500")) << "failure reply";
    }
    void malformed()
    {
        QFETCH(QByteArray, wire);
        QFETCH(QString, why);
        const Decoded<Frame> d = decodeRtu(wire);
        QVERIFY(!d.ok());
        QVERIFY2(d.error.contains(why), qPrintable(d.error));
    }

    void everySingleBitFlipIsCaught()
    {
        const QByteArray good = hex("012504e80300003895");
        QVERIFY(decodeRtu(good).ok()); // else every flip "is caught" by a decoder that takes nothing
        for (int i = 0; i < good.size(); ++i) {
            for (int bit = 0; bit < 8; ++bit) {
                QByteArray bad = good;
                bad[i] = static_cast<char>(bad[i] ^ (1 << bit));
                // CRC-16 detects every single-bit error: no flipped frame may decode at all (to
                // another frame no more than to this one).
                const Decoded<Frame> d = decodeRtu(bad);
                QVERIFY2(!d.ok(), qPrintable(bad.toHex()));
            }
        }
    }

    // ---- stream parser ----

    void streamWholeTable()
    {
        QByteArray stream;
        const QList<Frame> frames = everyRtuFrame();
        for (const Frame &f : frames)
            stream += rtuBytes(f);
        RtuStreamParser parser;
        const QList<Frame> got = parser.feed(stream);
        QCOMPARE(got, frames);
        QCOMPARE(parser.discardedBytes(), quint64(0));
        QCOMPARE(parser.bufferedSize(), 0);
    }

    void streamByteAtATime()
    {
        QByteArray stream;
        QList<Frame> frames = everyRtuFrame();
        for (const Frame &f : frames)
            stream += rtuBytes(f);
        RtuStreamParser parser;
        QList<Frame> got;
        for (const char c : stream) {
            got += parser.feed(QByteArray(1, c));
            QVERIFY(parser.bufferedSize() <= parser.capacity());
        }
        QCOMPARE(got, frames);
        QCOMPARE(parser.discardedBytes(), quint64(0));
    }

    void streamTolerantLayouts()
    {
        RtuStreamParser parser;
        const QByteArray stream = hex("013606a0860100442f") + hex("01380000000000003804") + hex("0125003a90")
            + hex("01a50104000000"
                  "0084dc")
            + hex("012502bb51");
        QList<Frame> got;
        QList<RtuLayout> layouts;
        for (const char c : stream) {
            for (const Frame &f : parser.feed(QByteArray(1, c))) {
                got.append(f);
                layouts.append(parser.lastLayout());
            }
        }
        QCOMPARE(got,
                 (QList<Frame>{Frame::make(1, 0x36, hex("a0860100")), Frame::make(1, 0x38), Frame::make(1, 0x25),
                               Frame::failureReply(1, 0x25, 4), Frame::make(1, 0x25)}));
        QCOMPARE(layouts,
                 (QList<RtuLayout>{RtuLayout::LengthCountsCrc, RtuLayout::FixedLength, RtuLayout::Standard,
                                   RtuLayout::FixedLength, RtuLayout::LengthCountsCrc}));
    }

    void streamNoiseBeforeAndBetween()
    {
        const QByteArray a = hex("013604a08601003def");
        const QByteArray b = hex("01a5010411a8");
        const QByteArray c = hex("0121003850");
        RtuStreamParser parser;
        const QByteArray stream = hex("ff00fe3601") + a + hex("0000") + b + hex("13") + c + hex("7f");
        const QList<Frame> got = parser.feed(stream);
        QCOMPARE(got, (QList<Frame>{*decodeRtu(a).value, *decodeRtu(b).value, *decodeRtu(c).value}));
        QCOMPARE(parser.discardedBytes(), quint64(5 + 2 + 1));
        QCOMPARE(parser.bufferedSize(), 1); // the trailing 0x7f may still start a frame
    }

    void streamTruncatedFrameThenFrame()
    {
        // A reply cut short (e.g. by a timeout on the drive side) followed by a whole one:
        // the cut one's len promises more bytes, but the whole frame behind it wins.
        const QByteArray whole = hex("013604a08601003def");
        RtuStreamParser parser;
        QList<Frame> got;
        for (const char ch : hex("013604a086") + whole)
            got += parser.feed(QByteArray(1, ch));
        QCOMPARE(got, (QList<Frame>{*decodeRtu(whole).value}));
        QCOMPARE(parser.discardedBytes(), quint64(5));
    }

    void streamBadCrcIsSkipped()
    {
        RtuStreamParser parser;
        const QList<Frame> got = parser.feed(hex("013604a08601003dee") + hex("0121003850"));
        QCOMPARE(got, (QList<Frame>{Frame::make(1, 0x21)}));
        QCOMPARE(parser.discardedBytes(), quint64(9));
    }

    void streamIncompleteWaitsAndClears()
    {
        RtuStreamParser parser;
        QVERIFY(parser.feed(hex("013604a0")).isEmpty());
        QCOMPARE(parser.bufferedSize(), 4);
        QCOMPARE(parser.feed(hex("8601003def")), (QList<Frame>{Frame::make(1, 0x36, hex("a0860100"))}));
        QVERIFY(parser.feed(hex("013604")).isEmpty());
        parser.clear();
        QCOMPARE(parser.bufferedSize(), 0);
        QCOMPARE(parser.feed(hex("0121003850")), (QList<Frame>{Frame::make(1, 0x21)}));
    }

    void streamBufferIsBounded()
    {
        RtuStreamParser parser({}, 64);
        QCOMPARE(parser.capacity(), 64);
        // Never taken: the buffer stays at capacity, oldest bytes go first.
        for (int i = 0; i < 100; ++i)
            parser.append(QByteArray(7, '\x01'));
        QCOMPARE(parser.bufferedSize(), 64);
        QCOMPARE(parser.discardedBytes(), quint64(700 - 64));
        parser.append(QByteArray(1000, '\x02'));
        QCOMPARE(parser.bufferedSize(), 64);
        QCOMPARE(parser.discardedBytes(), quint64(1700 - 64));
        parser.clear();
        // A frame after lots of garbage still comes out.
        QByteArray junk(5000, '\0');
        for (int i = 0; i < junk.size(); ++i)
            junk[i] = static_cast<char>(i * 7);
        QCOMPARE(parser.feed(junk + hex("0121003850")), (QList<Frame>{Frame::make(1, 0x21)}));
        QVERIFY(parser.bufferedSize() <= 64);
        // A tiny capacity is raised to hold the longest frame twice.
        QVERIFY(RtuStreamParser({}, 1).capacity() >= 2 * (RtuStreamParser::kMaxDataLength + kRtuOverhead));
    }

    void streamRandomNoise()
    {
        // Frames separated by random noise, fed in random chunk sizes: every frame comes
        // out, in order (noise here never forms a frame with a valid CRC by chance).
        Lcg rng{12345};
        const QList<Frame> frames = everyRtuFrame();
        QByteArray stream;
        for (const Frame &f : frames) {
            const int noise = rng.next() % 12;
            for (int i = 0; i < noise; ++i)
                stream.append(static_cast<char>(rng.next()));
            stream += rtuBytes(f);
        }
        RtuStreamParser parser;
        QList<Frame> got;
        for (qsizetype at = 0; at < stream.size();) {
            const int chunk = 1 + rng.next() % 20;
            got += parser.feed(stream.mid(at, chunk));
            at += chunk;
        }
        QCOMPARE(got, frames);
    }

    void streamPureNoiseNeverCrashes()
    {
        Lcg rng{777};
        RtuStreamParser parser({}, 128);
        for (int round = 0; round < 2000; ++round) {
            QByteArray chunk;
            const int n = rng.next() % 40;
            for (int i = 0; i < n; ++i)
                chunk.append(static_cast<char>(rng.next()));
            const QList<Frame> frames = parser.feed(chunk);
            for (const Frame &f : frames) // anything that comes out re-encodes to a frame that checks
                QVERIFY(decodeRtu(rtuBytes(f)).ok());
            QVERIFY(parser.bufferedSize() <= parser.capacity());
        }
    }

private:
    static QByteArray withCrcOf(const QByteArray &bytes) { return dd::withCrc16(bytes); }
};

QTEST_APPLESS_MAIN(TestShuokeRtu)
#include "tst_shuokertu.moc"
