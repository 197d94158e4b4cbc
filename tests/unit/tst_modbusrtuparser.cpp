#include <QtTest>

#include "core/protocol/modbus/crc16.h"
#include "core/protocol/modbus/modbusrtuparser.h"
#include "tests/support/hex.h"

#include <QRandomGenerator>

using namespace dd;
using Mode = ModbusRtuStreamParser::Mode;
using FrameState = ModbusRtuStreamParser::FrameState;

namespace {

using dd::test::hex;

// Drive side (requests), address 5.
const QByteArray R_read = hex("05 03 00 64 00 14 05 9E");                 // read PA0..PA19
const QByteArray R_write = hex("05 10 00 64 00 02 04 00 01 FF FE 70 F4"); // PA0 = 1, PA1 = -2
const QByteArray R_eeLegacy = hex("05 06 00 00 00 01 49 8E");             // EE-Set, legacy
const QByteArray R_eeNew = hex("05 10 00 3A 00 01 02 00 01 50 0A");       // EE-Set, new

// Host side (replies).
const QByteArray A_read = hex("05 03 04 00 01 FF FE 2E 43");
const QByteArray A_write = hex("05 10 00 64 00 02 01 93");
const QByteArray A_eeRunning = hex("05 06 00 00 00 00 88 4E");
const QByteArray A_exception = hex("01 83 04 40 F3");

QList<QByteArray> drain(ModbusRtuStreamParser &p)
{
    QList<QByteArray> out;
    while (p.hasFrame())
        out.append(p.takeFrame());
    return out;
}

void feedBytewise(ModbusRtuStreamParser &p, const QByteArray &stream)
{
    for (char c : stream)
        p.feed(QByteArray(1, c));
}

QList<QByteArray> hexList(const QList<QByteArray> &frames)
{
    QList<QByteArray> out;
    for (const auto &f : frames)
        out.append(f.toHex(' '));
    return out;
}

} // namespace

class TestModbusRtuParser : public QObject
{
    Q_OBJECT
private slots:
    void requestsWholeFrames()
    {
        ModbusRtuStreamParser p(Mode::Requests);
        p.feed(R_read + R_write + R_eeLegacy + R_eeNew);
        QCOMPARE(hexList(drain(p)), hexList({R_read, R_write, R_eeLegacy, R_eeNew}));
        QCOMPARE(p.discardedBytes(), quint64(0));
        QCOMPARE(p.pendingBytes(), qsizetype(0));
    }
    void repliesWholeFrames()
    {
        ModbusRtuStreamParser p(Mode::Replies);
        p.feed(A_read + A_write + A_eeRunning + A_exception);
        QCOMPARE(hexList(drain(p)), hexList({A_read, A_write, A_eeRunning, A_exception}));
        QCOMPARE(p.discardedBytes(), quint64(0));
    }
    void oneByteAtATime()
    {
        ModbusRtuStreamParser req(Mode::Requests);
        const QByteArray requests = R_write + R_read + R_eeNew + R_eeLegacy;
        for (qsizetype i = 0; i < requests.size(); ++i) {
            req.feed(requests.mid(i, 1));
            // Nothing is delivered before the last byte of a frame arrives.
            const bool frameEnds = i + 1 == R_write.size() || i + 1 == R_write.size() + R_read.size()
                || i + 1 == R_write.size() + R_read.size() + R_eeNew.size() || i + 1 == requests.size();
            QCOMPARE(req.hasFrame(), frameEnds);
            drain(req);
            QVERIFY(req.takeFrame().isEmpty());
        }
        QCOMPARE(req.discardedBytes(), quint64(0));

        ModbusRtuStreamParser rep(Mode::Replies);
        feedBytewise(rep, A_exception + A_read + A_eeRunning + A_write);
        QCOMPARE(hexList(drain(rep)), hexList({A_exception, A_read, A_eeRunning, A_write}));
        QCOMPARE(rep.discardedBytes(), quint64(0));
    }
    void truncatedFrameWaits()
    {
        ModbusRtuStreamParser p(Mode::Replies);
        p.feed(A_read.left(6));
        QVERIFY(!p.hasFrame());
        QCOMPARE(p.pendingBytes(), qsizetype(6));
        p.feed(A_read.mid(6));
        QCOMPARE(hexList(drain(p)), hexList({A_read}));
        QCOMPARE(p.discardedBytes(), quint64(0));
    }
    void truncatedFrameThenSilence()
    {
        ModbusRtuStreamParser p(Mode::Requests);
        p.feed(R_write.left(10));
        QCOMPARE(p.discardPending(), qsizetype(10));
        QCOMPARE(p.discardedBytes(), quint64(10));
        p.feed(R_read);
        QCOMPARE(hexList(drain(p)), hexList({R_read}));
    }
    void truncatedFrameFollowedByAFrame()
    {
        // The cut-off frame's claimed length swallows bytes of the next one; the CRC fails,
        // the parser slides on and finds the next frame.
        for (bool bytewise : {false, true}) {
            ModbusRtuStreamParser p(Mode::Replies);
            const QByteArray stream = A_read.left(5) + A_write;
            bytewise ? feedBytewise(p, stream) : p.feed(stream);
            QCOMPARE(hexList(drain(p)), hexList({A_write}));
            QCOMPARE(p.discardedBytes(), quint64(5));
            QCOMPARE(p.pendingBytes(), qsizetype(0));
        }
    }
    void badCrcDiscarded()
    {
        for (bool bytewise : {false, true}) {
            QByteArray bad = A_read;
            bad[bad.size() - 1] = static_cast<char>(bad.back() ^ 0x01);
            ModbusRtuStreamParser p(Mode::Replies);
            const QByteArray stream = bad + A_write;
            bytewise ? feedBytewise(p, stream) : p.feed(stream);
            QCOMPARE(hexList(drain(p)), hexList({A_write}));
            QCOMPARE(p.discardedBytes(), quint64(bad.size()));

            QByteArray badReq = R_eeNew;
            badReq[8] = 0x02; // EE-rd in the data, CRC still of EE-Set
            ModbusRtuStreamParser q(Mode::Requests);
            const QByteArray reqStream = badReq + R_read;
            bytewise ? feedBytewise(q, reqStream) : q.feed(reqStream);
            QCOMPARE(hexList(drain(q)), hexList({R_read}));
            QCOMPARE(q.discardedBytes(), quint64(badReq.size()));
        }
    }
    void noiseBeforeAndBetween()
    {
        const QByteArray n1 = hex("FF 00 AA"), n2 = hex("12 34"), n3 = hex("FE");
        for (bool bytewise : {false, true}) {
            ModbusRtuStreamParser p(Mode::Replies);
            const QByteArray stream = n1 + A_read + n2 + A_write + A_eeRunning + n3 + A_exception;
            bytewise ? feedBytewise(p, stream) : p.feed(stream);
            QCOMPARE(hexList(drain(p)), hexList({A_read, A_write, A_eeRunning, A_exception}));
            QCOMPARE(p.discardedBytes(), quint64(n1.size() + n2.size() + n3.size()));
            QCOMPARE(p.pendingBytes(), qsizetype(0));

            ModbusRtuStreamParser q(Mode::Requests);
            const QByteArray reqStream = n1 + R_write + n2 + R_read + n3 + R_eeLegacy;
            bytewise ? feedBytewise(q, reqStream) : q.feed(reqStream);
            QCOMPARE(hexList(drain(q)), hexList({R_write, R_read, R_eeLegacy}));
            QCOMPARE(q.discardedBytes(), quint64(n1.size() + n2.size() + n3.size()));
        }
    }
    void unknownFunctionResyncs()
    {
        // A 0x04 request is not this drive's: its bytes are discarded one by one.
        const QByteArray fc04 = hex("05 04 00 00 00 01 30 4E");
        ModbusRtuStreamParser p(Mode::Requests);
        p.feed(fc04 + R_read);
        QCOMPARE(hexList(drain(p)), hexList({R_read}));
        QCOMPARE(p.discardedBytes(), quint64(fc04.size()));
    }
    void impossibleHeadersAreNoise()
    {
        // 0x10 request whose byte count is not 2 x count; 0x03 reply with odd or zero count.
        ModbusRtuStreamParser q(Mode::Requests);
        q.feed(hex("05 10 00 64 00 02 05"));
        QCOMPARE(q.pendingBytes(), qsizetype(1)); // only the trailing byte could still start a frame
        ModbusRtuStreamParser p(Mode::Replies);
        p.feed(hex("05 03 05 00"));
        QCOMPARE(p.pendingBytes(), qsizetype(1));
        p.reset();
        p.feed(hex("05 03 00 00"));
        QCOMPARE(p.pendingBytes(), qsizetype(1));
        // A request is not a reply: 0x03 request bytes read as a reply have byte count 0.
        p.reset();
        p.feed(R_read + A_write);
        QCOMPARE(hexList(drain(p)), hexList({A_write}));
        QCOMPARE(p.discardedBytes(), quint64(R_read.size()));
    }
    void lookAheadFreesAFrameStuckBehindNoise()
    {
        // "07 03 28" looks like the header of a 45-byte reply; the real frame after it is
        // delivered at once instead of waiting for 45 bytes.
        ModbusRtuStreamParser p(Mode::Replies);
        p.feed(hex("07 03 28") + A_write);
        QCOMPARE(hexList(drain(p)), hexList({A_write}));
        QCOMPARE(p.discardedBytes(), quint64(3));
        QCOMPARE(p.pendingBytes(), qsizetype(0));

        ModbusRtuStreamParser q(Mode::Requests);
        feedBytewise(q, hex("09 10 00 01 00 0A 14") + R_read);
        QCOMPARE(hexList(drain(q)), hexList({R_read}));
        QCOMPARE(q.discardedBytes(), quint64(7));
    }
    void bufferCapBoundsFrameLengthAndPendingBytes()
    {
        ModbusRtuStreamParser small(Mode::Replies, 45); // 20 registers at most
        ModbusRtuStreamParser big(Mode::Replies);
        QCOMPARE(small.bufferCap(), 45);
        QCOMPARE(big.bufferCap(), 256);
        // A header claiming 47 bytes is noise under a cap of 45, a pending frame otherwise.
        small.feed(hex("01 03 2A 00"));
        big.feed(hex("01 03 2A 00"));
        QCOMPARE(small.pendingBytes(), qsizetype(1));
        QCOMPARE(big.pendingBytes(), qsizetype(4));

        // The longest frame within the cap passes, a longer one does not.
        QByteArray twenty = hex("05 03 28") + QByteArray(40, '\x11');
        QByteArray twentyTwo = hex("05 03 2C") + QByteArray(44, '\x11');
        twenty = withCrc16(twenty);
        twentyTwo = withCrc16(twentyTwo);
        small.reset();
        small.feed(twenty + twentyTwo + A_write);
        QCOMPARE(hexList(drain(small)), hexList({twenty, A_write}));
        QCOMPARE(small.discardedBytes(), quint64(twentyTwo.size()));
        big.reset();
        big.feed(twenty + twentyTwo + A_write);
        QCOMPARE(hexList(drain(big)), hexList({twenty, twentyTwo, A_write}));

        ModbusRtuStreamParser tiny(Mode::Requests, 3);
        QCOMPARE(tiny.bufferCap(), ModbusRtuStreamParser::MinBufferCap);
    }
    void noiseNeverGrowsTheBuffer()
    {
        QRandomGenerator rng(20240611);
        for (Mode mode : {Mode::Requests, Mode::Replies}) {
            for (int cap : {8, 45, 256, 1024}) {
                ModbusRtuStreamParser p(mode, cap);
                quint64 fed = 0, delivered = 0;
                for (int round = 0; round < 200; ++round) {
                    QByteArray chunk(rng.bounded(1, 300), Qt::Uninitialized);
                    for (auto &c : chunk)
                        c = static_cast<char>(rng.bounded(256));
                    // Bias towards plausible headers so that long pending frames happen.
                    if (round % 3 == 0)
                        chunk.prepend(mode == Mode::Requests ? hex("05 10 00 64 00 7F FE") : hex("05 03 FE"));
                    p.feed(chunk);
                    fed += chunk.size();
                    QVERIFY(p.pendingBytes() < cap);
                    for (const QByteArray &f : drain(p))
                        delivered += f.size();
                }
                QCOMPARE(p.discardedBytes() + delivered + quint64(p.pendingBytes()), fed);
                QVERIFY(p.discardedBytes() > 0);
            }
        }
    }
    void queueIsBounded()
    {
        QByteArray many;
        for (int i = 0; i < 100; ++i)
            many += A_write;
        ModbusRtuStreamParser p(Mode::Replies);
        p.feed(many); // one chunk far larger than the buffer cap: framed as it goes
        const auto frames = drain(p);
        QCOMPARE(frames.size(), ModbusRtuStreamParser::DefaultMaxQueuedFrames);
        QCOMPARE(p.droppedFrames(), quint64(100 - ModbusRtuStreamParser::DefaultMaxQueuedFrames));
        QCOMPARE(p.discardedBytes(), quint64(0));

        QByteArray fifty;
        for (int i = 0; i < 50; ++i)
            fifty += R_write;
        ModbusRtuStreamParser q(Mode::Requests);
        q.feed(fifty); // 650 bytes in one call
        QCOMPARE(drain(q).size(), 50);
        QCOMPARE(q.droppedFrames(), quint64(0));
    }
    void resetClearsEverything()
    {
        ModbusRtuStreamParser p(Mode::Replies);
        p.feed(hex("FF") + A_write + A_read.left(3));
        QVERIFY(p.hasFrame());
        QCOMPARE(p.discardedBytes(), quint64(1));
        p.reset();
        QVERIFY(!p.hasFrame());
        QCOMPARE(p.pendingBytes(), qsizetype(0));
        QCOMPARE(p.discardedBytes(), quint64(0));
        QCOMPARE(p.mode(), Mode::Replies);
    }

    // ---- checkFrame: the reply matcher's "complete?" ----
    void checkFrameComplete()
    {
        auto c = ModbusRtuStreamParser::checkFrame(A_read, Mode::Replies);
        QCOMPARE(c.state, FrameState::Complete);
        QCOMPARE(c.offset, qsizetype(0));
        QCOMPARE(c.length, qsizetype(A_read.size()));

        c = ModbusRtuStreamParser::checkFrame(A_exception + hex("00 00"), Mode::Replies);
        QCOMPARE(c.state, FrameState::Complete);
        QCOMPARE(c.length, qsizetype(5)); // trailing bytes are not part of it

        c = ModbusRtuStreamParser::checkFrame(R_write, Mode::Requests);
        QCOMPARE(c.state, FrameState::Complete);
        QCOMPARE(c.length, qsizetype(R_write.size()));
    }
    void checkFrameIncomplete()
    {
        for (int n = 0; n < A_read.size(); ++n) {
            const auto c = ModbusRtuStreamParser::checkFrame(A_read.left(n), Mode::Replies);
            QCOMPARE(c.state, FrameState::Incomplete);
            QCOMPARE(c.offset, qsizetype(0));
        }
        const auto c = ModbusRtuStreamParser::checkFrame(hex("FF FF FF"), Mode::Replies);
        QCOMPARE(c.state, FrameState::Incomplete);
        QCOMPARE(c.offset, qsizetype(2)); // the last byte could still start a frame
    }
    void checkFrameSkipsLocalEcho()
    {
        // Some RS485 adapters echo what they send: the request, then the reply.
        const QByteArray echoAndReply = R_read + A_read;
        for (int n = R_read.size(); n < echoAndReply.size(); ++n)
            QCOMPARE(ModbusRtuStreamParser::checkFrame(echoAndReply.left(n), Mode::Replies).state,
                     FrameState::Incomplete);
        const auto c = ModbusRtuStreamParser::checkFrame(echoAndReply, Mode::Replies);
        QCOMPARE(c.state, FrameState::Complete);
        QCOMPARE(c.offset, qsizetype(R_read.size()));
        QCOMPARE(c.length, qsizetype(A_read.size()));
    }
    void checkFrameToleratesUnknownFunction()
    {
        // 0x04 reply (not a function of ours) with a good CRC: complete, for the decoder to name.
        const QByteArray fc04 = hex("05 04 02 00 01 89 30");
        auto c = ModbusRtuStreamParser::checkFrame(fc04, Mode::Replies);
        QCOMPARE(c.state, FrameState::Complete);
        QCOMPARE(c.length, qsizetype(fc04.size()));
        c = ModbusRtuStreamParser::checkFrame(fc04.left(6), Mode::Replies);
        QCOMPARE(c.state, FrameState::Incomplete);
        // Requests mode is not tolerant that way.
        c = ModbusRtuStreamParser::checkFrame(fc04, Mode::Requests);
        QCOMPARE(c.state, FrameState::Incomplete);
    }
};

QTEST_APPLESS_MAIN(TestModbusRtuParser)
#include "tst_modbusrtuparser.moc"
