// SerialLink on a real pty, with the test as the drive: stale input before a request, and
// the command spacing a drive counts (shuoke's 50 ms between commands).
#include <QtTest>

#include <QElapsedTimer>
#include <QSignalSpy>

#include "core/link/linkreply.h"
#include "core/link/seriallink.h"
#include "core/link/traffictap.h"
#include "sim/bus/ptyendpoint.h"
#include "tests/support/requiretool.h"

using namespace dd;

namespace {

// A reply is the request's first byte followed by 0xAA 0xBB and one value byte.
ReplyMatcher replyOf(char first)
{
    return [first](const QByteArray &b) -> FrameMatch {
        if (b.size() < 4)
            return FrameMatch::incomplete();
        if (b.at(0) != first || quint8(b.at(1)) != 0xAA || quint8(b.at(2)) != 0xBB)
            return FrameMatch::garbage(1);
        return FrameMatch::match(4, b.left(4));
    };
}

QByteArray reply(char first, quint8 value)
{
    QByteArray r;
    r.append(first).append(char(0xAA)).append(char(0xBB)).append(char(value));
    return r;
}

bool waitFinished(LinkReply *r, int ms = 3000)
{
    if (r->isFinished())
        return true;
    QSignalSpy spy(r, &LinkReply::finished);
    return spy.wait(ms);
}

} // namespace

class TestSerialLink : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase() { DD_REQUIRE_TOOL(PtyEndpoint::isSupported(), "no pseudo-terminals on this system"); }

    // A reply of the right shape that was already waiting (unread) when the request went out
    // answers an earlier question: it must not be taken for this request's answer.
    void inputWaitingBeforeARequestIsNeverItsAnswer()
    {
        PtyEndpoint pty;
        QVERIFY(!pty.open());
        SerialLink link;
        SerialSettings s;
        s.portName = pty.clientPath();
        s.baud = 115200;
        s.retries = 0;
        QVERIFY(link.open(s));
        QByteArray seen;
        connect(&pty, &PtyEndpoint::received, this, [&](const QByteArray &b) {
            seen += b;
            if (seen.endsWith("Q1"))
                pty.write(reply('Q', 0x22)); // the real answer
        });
        // A stale copy reaches the port while nothing is pending and the event loop has not
        // read it yet; the request leaves at once (the link is idle).
        QCOMPARE(pty.write(reply('Q', 0x11)), 4);
        QTest::qSleep(20); // no event loop: the pty delivers it to the client's side, unread
        SerialRequest q;
        q.bytes = "Q1";
        q.matcher = replyOf('Q');
        LinkReply *r = link.send(q);
        QVERIFY(waitFinished(r));
        QVERIFY2(!r->error().isError(), qPrintable(r->error().message));
        QCOMPARE(r->frame(), reply('Q', 0x22));
    }

    // The adapter is gone when a request goes out: the port reports it from inside the
    // write (the link pushes the request to the driver at once). The request fails with
    // LinkClosed and the link closes; before, the link went on using the request it had
    // just failed (a crash in tst_faultshuoke under load, and in the trace).
    void portFailingAsARequestLeavesFailsItCleanly()
    {
        PtyEndpoint pty;
        QVERIFY(!pty.open());
        SerialLink link;
        TrafficTap tap;
        link.setTap(&tap);
        SerialSettings s;
        s.portName = pty.clientPath();
        s.baud = 115200;
        s.retries = 0;
        QVERIFY(link.open(s));
        QSignalSpy closed(&link, &SerialLink::closed);
        pty.close(); // no event loop yet: the link has not noticed
        SerialRequest q;
        q.bytes = "Q1";
        q.matcher = replyOf('Q');
        LinkReply *r = link.send(q);
        QVERIFY(waitFinished(r));
        QCOMPARE(r->error().code, ErrorCode::LinkClosed);
        QTRY_COMPARE(closed.count(), 1);
        QVERIFY(!link.isOpen());
        QVERIFY(link.isIdle());
    }

    // Commands reach the drive minCommandSpacingMs apart (last byte to last byte), however
    // quickly it answers; the count starts at the reply's first byte (the drive had the
    // whole command by then), not at its end plus a gap. (The simulated bus, which models
    // wire time, checks the drive's view: tst_shuokeserialrtu.)
    void commandSpacingIsKept()
    {
        PtyEndpoint pty;
        QVERIFY(!pty.open());
        SerialLink link;
        SerialSettings s;
        s.portName = pty.clientPath();
        s.baud = 115200;
        s.minGapMs = 1;
        s.minCommandSpacingMs = 30;
        QVERIFY(link.open(s));
        QElapsedTimer clock;
        clock.start();
        QList<qint64> commandAt;
        QByteArray seen;
        // The "drive" answers each 2-byte command 2 ms after it came.
        connect(&pty, &PtyEndpoint::received, this, [&](const QByteArray &b) {
            seen += b;
            while (seen.size() >= 2) {
                const char first = seen.at(0);
                seen.remove(0, 2);
                commandAt << clock.nsecsElapsed() / 1000;
                QTimer::singleShot(2, &pty, [&pty, first] { pty.write(reply(first, 1)); });
            }
        });
        QList<LinkReply *> replies;
        for (int i = 0; i < 6; ++i) {
            SerialRequest q;
            q.bytes = QByteArray("C") + char('0' + i);
            q.matcher = replyOf('C');
            replies << link.send(q);
        }
        for (LinkReply *r : replies) {
            QVERIFY(waitFinished(r));
            QVERIFY2(!r->error().isError(), qPrintable(r->error().message));
        }
        QCOMPARE(commandAt.size(), 6);
        for (int i = 1; i < commandAt.size(); ++i) {
            const qint64 apart = commandAt[i] - commandAt[i - 1];
            QVERIFY2(apart >= 30000, qPrintable(QString::number(apart)));
        }
        // 30 ms + the 1 ms margin + the answer's 2 ms, and timer wake-ups; under what counting
        // from the reply's end plus a second gap would give (>= 62 ms). Measured 50-52 ms while
        // other builds loaded the machine (the old bound, 45 ms, failed there every time).
        const qint64 mean = (commandAt.last() - commandAt.first()) / (commandAt.size() - 1);
        qInfo("commands %lld us apart on average", static_cast<long long>(mean));
        QVERIFY2(mean < 60000, qPrintable(QString::number(mean)));
    }
};

QTEST_GUILESS_MAIN(TestSerialLink)
#include "tst_seriallink.moc"
