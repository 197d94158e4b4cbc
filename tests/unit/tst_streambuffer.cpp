// StreamBuffer: the bounded input buffer the Modbus RTU and Shuoke RTU / ASCII stream
// parsers share (their byte-exact behaviour: tst_modbusrtuparser, tst_shuokertu,
// tst_shuokeascii and the fuzz corpora).
#include "core/protocol/streambuffer.h"

#include <QtTest>

#include <optional>

using namespace dd;

class TestStreamBuffer : public QObject
{
    Q_OBJECT

private slots:
    void appendKeepsTheNewestBytes()
    {
        StreamBuffer b(8);
        b.append("abcdef");
        QCOMPARE(b.bytes(), QByteArray("abcdef"));
        QCOMPARE(b.discardedBytes(), quint64(0));
        b.append("ghij"); // two too many: the oldest go
        QCOMPARE(b.bytes(), QByteArray("cdefghij"));
        QCOMPARE(b.discardedBytes(), quint64(2));
        b.append("0123456789"); // longer than the capacity: its last 8 bytes stay
        QCOMPARE(b.bytes(), QByteArray("23456789"));
        QCOMPARE(b.discardedBytes(), quint64(2 + 8 + 2));
        QCOMPARE(b.size(), b.capacity());
    }

    void discardCountsTakeFrontDoesNot()
    {
        StreamBuffer b(16);
        b.append("xxFRAMErest");
        b.discard(2);
        QCOMPARE(b.takeFront(5), QByteArray("FRAME"));
        QCOMPARE(b.bytes(), QByteArray("rest"));
        QCOMPARE(b.discardedBytes(), quint64(2));
        b.discard(0);
        b.discard(-3);
        QCOMPARE(b.discardedBytes(), quint64(2));
        b.discard(100); // no more than there is
        QVERIFY(b.isEmpty());
        QCOMPARE(b.discardedBytes(), quint64(6));
        QCOMPARE(b.takeFront(3), QByteArray());
    }

    void clearKeepsTheCountResetZeroesIt()
    {
        StreamBuffer b(16);
        b.append("noise");
        b.discard(2);
        b.clear();
        QVERIFY(b.isEmpty());
        QCOMPARE(b.discardedBytes(), quint64(2));
        b.append("abc");
        b.reset();
        QVERIFY(b.isEmpty());
        QCOMPARE(b.discardedBytes(), quint64(0));
    }

    void appendInSlicesDrainsAfterEachSlice()
    {
        // A drain that takes 4-byte "frames" loses nothing, however long the input.
        StreamBuffer b(8);
        QByteArray in;
        for (int i = 0; i < 10; ++i)
            in += QByteArray::number(1000 + i);
        QList<QByteArray> frames;
        int drains = 0;
        b.appendInSlices(in, [&] {
            ++drains;
            while (b.size() >= 4)
                frames << b.takeFront(4);
        });
        QCOMPARE(frames.size(), 10);
        QCOMPARE(frames.first(), QByteArray("1000"));
        QCOMPARE(frames.last(), QByteArray("1009"));
        QCOMPARE(b.discardedBytes(), quint64(0));
        QCOMPARE(drains, 5); // 8 bytes at a time
    }

    void appendInSlicesOfAFullBufferPushesOutOneByteAtATime()
    {
        StreamBuffer b(8);
        b.append("abcdefgh");
        int drains = 0;
        b.appendInSlices("xy", [&] { ++drains; });
        QCOMPARE(drains, 2);
        QCOMPARE(b.bytes(), QByteArray("cdefghxy"));
        QCOMPARE(b.discardedBytes(), quint64(2));
    }

    void appendAndTakeFramesCollectsInOrder()
    {
        StreamBuffer b(8);
        const QList<QByteArray> frames = b.appendAndTakeFrames("aaabbbcccdd", [&b]() -> std::optional<QByteArray> {
            if (b.size() < 3)
                return std::nullopt;
            return b.takeFront(3);
        });
        QCOMPARE(frames, (QList<QByteArray>{"aaa", "bbb", "ccc"}));
        QCOMPARE(b.bytes(), QByteArray("dd"));
    }

    void appendInSlicesDrainsOnceForNothing()
    {
        StreamBuffer b(8);
        int drains = 0;
        b.appendInSlices(QByteArray(), [&] { ++drains; });
        QCOMPARE(drains, 1);
    }
};

QTEST_GUILESS_MAIN(TestStreamBuffer)
#include "tst_streambuffer.moc"
