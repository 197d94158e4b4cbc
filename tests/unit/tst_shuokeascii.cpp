#include <QtTest>

#include "core/protocol/shuoke/shuokeascii.h"
#include "core/protocol/shuoke/shuokeasciistreamparser.h"
#include "core/protocol/shuoke/shuokecommands.h"
#include "tests/support/hex.h"
#include "tests/support/shuokeframestring.h"

using namespace dd::shuoke;
using dd::Decoded;

namespace {

using dd::test::hex;
QByteArray asciiData(int n, int seed)
{
    QByteArray d;
    for (int i = 0; i < n; ++i)
        d.append(static_cast<char>(0x11 * (i + 1) + seed));
    return d;
}
QByteArray ascii(const Frame &f, const AsciiOptions &o = {})
{
    const auto e = encodeAscii(f, o);
    return e.ok() ? *e.value : QByteArray("encode failed");
}
AsciiOptions twos()
{
    AsciiOptions o;
    o.check = AsciiCheck::TwosComplement;
    return o;
}

QList<Frame> everyAsciiFrame()
{
    QList<Frame> out;
    int seed = 0;
    for (const CommandInfo &c : commandTable()) {
        for (int n = 0; n < 16; ++n)
            if (c.allowsRequestLength(n))
                out.append(Frame::make(9, c.code, asciiData(n, seed++)));
        for (const quint8 reply : c.replyCommands)
            for (int n = 0; reply && n < 16; ++n)
                if (c.allowsReplyLength(n))
                    out.append(Frame::make(9, reply, asciiData(n, seed++)));
        out.append(Frame::failureReply(9, c.code, static_cast<quint8>(1 + seed++ % 5)));
    }
    return out;
}

} // namespace

class TestShuokeAscii : public QObject
{
    Q_OBJECT
private slots:
    void checkByte()
    {
        QCOMPARE(asciiCheckByte(hex("01220102")), quint8(0x26));
        QCOMPARE(asciiCheckByte(hex("01220102"), AsciiCheck::TwosComplement), quint8(0xDA));
        QCOMPARE(asciiCheckByte(hex("ff0203")), quint8(0x04)); // low 8 bits of the sum
        QCOMPARE(asciiCheckByte(QByteArray()), quint8(0));
        QCOMPARE(asciiCheckByte(QByteArray(), AsciiCheck::TwosComplement), quint8(0));
    }

    // The seed's worked example (change address 1 -> 2) and more frames built the same way.
    void examples_data()
    {
        QTest::addColumn<Frame>("frame");
        QTest::addColumn<bool>("twosComplement");
        QTest::addColumn<QByteArray>("wire");
        QTest::newRow("seed: change address")
            << Frame::make(1, 0x22, hex("02")) << false << QByteArray(":0122010226\r\n");
        QTest::newRow("seed: reply from new address")
            << Frame::make(2, 0x22, hex("02")) << false << QByteArray(":0222010227\r\n");
        QTest::newRow("two's complement") << Frame::make(1, 0x22, hex("02")) << true << QByteArray(":01220102DA\r\n");
        QTest::newRow("query address broadcast") << Frame::make(0, 0x21) << false << QByteArray(":00210021\r\n");
        QTest::newRow("query address, two's") << Frame::make(0, 0x21) << true << QByteArray(":002100DF\r\n");
        QTest::newRow("speed reply") << Frame::make(1, 0x36, hex("a0860100")) << false
                                     << QByteArray(":013604A086010062\r\n");
        QTest::newRow("speed reply, two's")
            << Frame::make(1, 0x36, hex("a0860100")) << true << QByteArray(":013604A08601009E\r\n");
        QTest::newRow("set start speed 1000")
            << Frame::make(1, 0x25, hex("e8030000")) << false << QByteArray(":012504E803000015\r\n");
        QTest::newRow("status reply") << Frame::make(1, 0x3B, hex("0100010001")) << false
                                      << QByteArray(":013B05010001000144\r\n");
        for (quint8 code = 1; code <= 5; ++code) {
            // 01 + A5 + 01 + code
            const QByteArray wire = QByteArray(":01A501") + QByteArray::number(code, 16).rightJustified(2, '0')
                + QByteArray::number(0xA7 + code, 16).toUpper() + "\r\n";
            QTest::addRow("failure code %d", code) << Frame::failureReply(1, 0x25, code) << false << wire;
        }
        QTest::newRow("failure, two's") << Frame::failureReply(1, 0x25, 4) << true << QByteArray(":01A5010455\r\n");
    }
    void examples()
    {
        QFETCH(Frame, frame);
        QFETCH(bool, twosComplement);
        QFETCH(QByteArray, wire);
        const AsciiOptions o = twosComplement ? twos() : AsciiOptions{};
        QCOMPARE(ascii(frame, o), wire);
        const Decoded<Frame> d = decodeAscii(wire, o);
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(*d.value, frame);
        // The other check convention rejects it.
        QVERIFY(!decodeAscii(wire, twosComplement ? AsciiOptions{} : twos()).ok());
    }

    void failureCodeSample() { QCOMPARE(ascii(Frame::failureReply(1, 0x25, 4)), QByteArray(":01A50104AB\r\n")); }

    void roundTripEveryCommand()
    {
        for (const Frame &f : everyAsciiFrame()) {
            for (const AsciiOptions &o : {AsciiOptions{}, twos()}) {
                const QByteArray wire = ascii(f, o);
                QCOMPARE(wire.size(), 1 + 2 * (3 + f.payload().size() + 1) + 2);
                QCOMPARE(wire, wire.toUpper());
                const Decoded<Frame> d = decodeAscii(wire, o);
                QVERIFY2(d.ok(), qPrintable(d.error + " " + wire));
                QCOMPARE(*d.value, f);
            }
        }
    }

    // Decision (docs/protocols/shuoke.md): len = asciiData + 1 is also accepted (the seed's "one less than RTU").
    void lengthPlusOne()
    {
        // 01 22 02 02: len 2 for 1 asciiData byte; sum 0x27
        const QByteArray wire(":0122020227\r\n");
        const Decoded<Frame> d = decodeAscii(wire);
        QVERIFY2(d.ok(), qPrintable(d.error));
        QCOMPARE(*d.value, Frame::make(1, 0x22, hex("02")));
        AsciiOptions strict;
        strict.acceptLengthPlusOne = false;
        QVERIFY(!decodeAscii(wire, strict).ok());
        // Failure reply with len 2
        QCOMPARE(*decodeAscii(":01A50204AC\r\n").value, Frame::failureReply(1, 0x25, 4));
        // len = asciiData + 2 is not accepted
        QVERIFY(!decodeAscii(":0122030228\r\n").ok());
        // len = asciiData - 1 neither
        QVERIFY(!decodeAscii(":0122000224\r\n").ok());
    }

    void tolerantReceive()
    {
        QCOMPARE(*decodeAscii(":01220102da\r\n", twos()).value, Frame::make(1, 0x22, hex("02"))); // lower case
        QCOMPARE(*decodeAscii(":0122010226\n").value, Frame::make(1, 0x22, hex("02")));           // bare LF
    }

    void malformed_data()
    {
        QTest::addColumn<QByteArray>("wire");
        QTest::addColumn<QString>("why");
        QTest::newRow("empty") << QByteArray() << "start";
        QTest::newRow("no colon") << QByteArray("0122010226\r\n") << "start";
        QTest::newRow("no terminator") << QByteArray(":0122010226") << "CR LF";
        QTest::newRow("CR only") << QByteArray(":0122010226\r") << "CR LF";
        QTest::newRow("odd digits") << QByteArray(":012201022\r\n") << "odd";
        QTest::newRow("non-hex G") << QByteArray(":01220G0226\r\n") << "non-hex";
        QTest::newRow("space") << QByteArray(":0122 010226\r\n") << "odd"; // 11 characters
        QTest::newRow("space, even") << QByteArray(":01 2010226\r\n") << "non-hex";
        QTest::newRow("CR inside") << QByteArray(":01\r2010226\r\n") << "non-hex";
        QTest::newRow("bad check") << QByteArray(":0122010227\r\n") << "check";
        QTest::newRow("too short") << QByteArray(":010203\r\n") << "too short";
        QTest::newRow("nothing") << QByteArray(":\r\n") << "too short";
        QTest::newRow("wrong length") << QByteArray(":012205022A\r\n") << "length";
        QTest::newRow("failure, 2 asciiData bytes") << QByteArray(":01A5020400AC\r\n") << "failure";
    }
    void malformed()
    {
        QFETCH(QByteArray, wire);
        QFETCH(QString, why);
        const Decoded<Frame> d = decodeAscii(wire);
        QVERIFY(!d.ok());
        QVERIFY2(d.error.contains(why), qPrintable(d.error));
    }

    // ---- stream parser ----

    void streamWholeTable()
    {
        QByteArray stream;
        const QList<Frame> frames = everyAsciiFrame();
        for (const Frame &f : frames)
            stream += ascii(f);
        AsciiStreamParser parser;
        QCOMPARE(parser.feed(stream), frames);
        QCOMPARE(parser.discardedBytes(), quint64(0));
        QCOMPARE(parser.rejectedFrames(), quint64(0));

        AsciiStreamParser bytewise;
        QList<Frame> got;
        for (const char c : stream)
            got += bytewise.feed(QByteArray(1, c));
        QCOMPARE(got, frames);
        QCOMPARE(bytewise.bufferedSize(), 0);
    }

    void streamNoiseBeforeAndBetween()
    {
        AsciiStreamParser parser;
        const QByteArray stream = QByteArray("\x00\xff junk\r\n", 10) + ":0122010226\r\n" + "zz\n\n" + ":0222010227\r\n"
            + "trailing";
        QCOMPARE(parser.feed(stream), (QList<Frame>{Frame::make(1, 0x22, hex("02")), Frame::make(2, 0x22, hex("02"))}));
        QCOMPARE(parser.rejectedFrames(), quint64(0));
        QCOMPARE(parser.discardedBytes(), quint64(10 + 4 + 8));
        QCOMPARE(parser.bufferedSize(), 0);
    }

    void streamInterruptedFrame()
    {
        AsciiStreamParser parser;
        QCOMPARE(parser.feed(":01220:0122010226\r\n"), (QList<Frame>{Frame::make(1, 0x22, hex("02"))}));
        QCOMPARE(parser.rejectedFrames(), quint64(1));
        QVERIFY(parser.lastError().contains(QLatin1String("interrupted")));
    }

    void streamNonHexRejectsFrame()
    {
        AsciiStreamParser parser;
        QCOMPARE(parser.feed(":01X2010226\r\n:0222010227\r\n"), (QList<Frame>{Frame::make(2, 0x22, hex("02"))}));
        QCOMPARE(parser.rejectedFrames(), quint64(1));
        QVERIFY(parser.lastError().contains(QLatin1String("non-hex")));
    }

    void streamBadCheckRejectsFrame()
    {
        AsciiStreamParser parser;
        QCOMPARE(parser.feed(":0122010227\r\n:0222010227\r\n"), (QList<Frame>{Frame::make(2, 0x22, hex("02"))}));
        QCOMPARE(parser.rejectedFrames(), quint64(1));
        QVERIFY(parser.lastError().contains(QLatin1String("check")));
        QCOMPARE(parser.discardedBytes(), quint64(13));
    }

    void streamWaitsForTerminator()
    {
        AsciiStreamParser parser;
        QVERIFY(parser.feed(":01220102").isEmpty());
        QVERIFY(parser.feed("26\r").isEmpty());
        QCOMPARE(parser.bufferedSize(), 12);
        QCOMPARE(parser.feed("\n"), (QList<Frame>{Frame::make(1, 0x22, hex("02"))}));
        QVERIFY(parser.feed(":0122").isEmpty());
        parser.clear();
        QCOMPARE(parser.bufferedSize(), 0);
    }

    void streamOverlongFrame()
    {
        AsciiStreamParser parser;
        const QByteArray longLine = ':' + QByteArray(AsciiStreamParser::kMaxFrameChars + 10, '0') + "\r\n";
        QCOMPARE(parser.feed(longLine + ":0122010226\r\n"), (QList<Frame>{Frame::make(1, 0x22, hex("02"))}));
        QCOMPARE(parser.rejectedFrames(), quint64(1));
        QVERIFY(parser.lastError().contains(QLatin1String("longer")));
        // A frame of exactly the maximum length is still read (16 asciiData bytes).
        const QByteArray maxFrame = ascii(Frame::make(1, 0x70, QByteArray(16, '\x01')));
        QCOMPARE(maxFrame.size(), AsciiStreamParser::kMaxFrameChars);
        QCOMPARE(parser.feed(maxFrame).size(), 1);
    }

    void streamBufferIsBounded()
    {
        AsciiStreamParser parser({}, 100);
        QCOMPARE(parser.capacity(), 100);
        for (int i = 0; i < 50; ++i)
            parser.append(QByteArray(":0000"));
        QCOMPARE(parser.bufferedSize(), 100);
        parser.append(QByteArray(5000, '0'));
        QCOMPARE(parser.bufferedSize(), 100);
        QVERIFY(parser.takeFrame() == std::nullopt);
        QVERIFY(parser.bufferedSize() <= 100);
        parser.clear();
        QCOMPARE(parser.feed(QByteArray(5000, 'x') + ":0122010226\r\n"),
                 (QList<Frame>{Frame::make(1, 0x22, hex("02"))}));
        QVERIFY(AsciiStreamParser({}, 1).capacity() >= 2 * AsciiStreamParser::kMaxFrameChars);
    }

    void streamRandomNoise()
    {
        quint32 state = 99;
        auto next = [&state] {
            state = state * 1103515245u + 12345u;
            return static_cast<quint8>(state >> 16);
        };
        const QList<Frame> frames = everyAsciiFrame();
        QByteArray stream;
        for (const Frame &f : frames) {
            const int noise = next() % 10;
            for (int i = 0; i < noise; ++i) {
                const char c = static_cast<char>(next());
                stream.append(c == ':' ? 'x' : c); // noise never starts a frame
            }
            stream += ascii(f);
        }
        AsciiStreamParser parser;
        QList<Frame> got;
        for (qsizetype at = 0; at < stream.size();) {
            const int chunk = 1 + next() % 16;
            got += parser.feed(stream.mid(at, chunk));
            at += chunk;
        }
        QCOMPARE(got, frames);
        QCOMPARE(parser.rejectedFrames(), quint64(0));
    }
};

QTEST_APPLESS_MAIN(TestShuokeAscii)
#include "tst_shuokeascii.moc"
