// SerialLink on a real pty, with the test as the drive: stale input before a request, and
// the command spacing a drive counts (shuoke's 50 ms between commands).
#include <QtTest>

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QThread>

#include "core/link/linkhealth.h"
#include "core/link/linkreply.h"
#include "core/link/seriallink.h"
#include "core/link/traffictap.h"
#include "sim/bus/ptyendpoint.h"
#include "tests/support/requiretool.h"

using namespace dd;

namespace {

// A reply is the request's first byte followed by 0xAA 0xBB and one value byte; the value
// DamagedValue makes it a reply that fails its check.
constexpr quint8 DamagedValue = 0xEE;

ReplyMatcher replyOf(char first)
{
    return [first](const QByteArray &b) -> FrameMatch {
        if (b.size() < 4)
            return FrameMatch::incomplete();
        if (b.at(0) != first || quint8(b.at(1)) != 0xAA || quint8(b.at(2)) != 0xBB)
            return FrameMatch::garbage(1);
        if (quint8(b.at(3)) == DamagedValue)
            return FrameMatch::corrupt(4); // a reply that fails its check
        return FrameMatch::match(4, b.left(4));
    };
}

QByteArray reply(char first, quint8 value)
{
    QByteArray r;
    r.append(first).append(char(0xAA)).append(char(0xBB)).append(char(value));
    return r;
}

bool waitSerial(LinkReply *r, int ms = 3000)
{
    if (r->isFinished())
        return true;
    QSignalSpy spy(r, &LinkReply::finished);
    return spy.wait(ms);
}

// The drive of framesOfOtherPeersAreNeverDroppedUnseen(), in a thread of its own so that its
// bytes land at any moment of the link's work: it answers every 2-byte "Q<n>" at once and,
// every millisecond, sends a frame of another peer ('F'), as the late answers of other
// drives land on a bus during a scan.
class BusyPeer : public QObject
{
    Q_OBJECT
public:
    // In the peer's thread: the path the link opens, empty when the pty failed.
    QString open()
    {
        m_pty = new PtyEndpoint(this);
        if (m_pty->open())
            return {};
        connect(m_pty, &PtyEndpoint::received, this, [this](const QByteArray &b) {
            m_seen += b;
            while (m_seen.size() >= 2) {
                if (m_answering)
                    m_pty->write(reply(m_seen.at(0), quint8(m_seen.at(1))));
                m_seen.remove(0, 2);
            }
        });
        m_spray = new QTimer(this);
        m_spray->setTimerType(Qt::PreciseTimer);
        m_spray->setInterval(1);
        connect(m_spray, &QTimer::timeout, this, [this] {
            if (m_pty->write(reply('F', quint8(m_sent))) == 4)
                ++m_sent;
        });
        return m_pty->clientPath();
    }
    void spray(bool on) { on ? m_spray->start() : m_spray->stop(); }
    int sent() const { return m_sent; }
    void setAnswering(bool on) { m_answering = on; }

private:
    bool m_answering = true;
    PtyEndpoint *m_pty = nullptr;
    QTimer *m_spray = nullptr;
    QByteArray m_seen;
    int m_sent = 0;
};

// A BusyPeer in a thread of its own, stopped and deleted with this.
class BusyPeerThread
{
public:
    BusyPeerThread()
        : m_peer(new BusyPeer)
    {
        m_peer->moveToThread(&m_thread);
        QObject::connect(&m_thread, &QThread::finished, m_peer, &QObject::deleteLater);
        m_thread.start();
        QMetaObject::invokeMethod(
            m_peer, [this] { m_path = m_peer->open(); }, Qt::BlockingQueuedConnection);
    }
    ~BusyPeerThread()
    {
        m_thread.quit();
        m_thread.wait();
    }
    QString path() const { return m_path; }
    // Runs f in the peer's thread and returns its result.
    template <typename F>
    auto call(F f)
    {
        decltype(f()) result{};
        QMetaObject::invokeMethod(
            m_peer, [&] { result = f(); }, Qt::BlockingQueuedConnection);
        return result;
    }
    BusyPeer *peer() const { return m_peer; }

private:
    QThread m_thread;
    BusyPeer *m_peer;
    QString m_path;
};

} // namespace

class TestSerialLink : public QObject
{
    Q_OBJECT
private:
    // What the "drive" of sendSpacedCommands() does with a command: it has it holdMs after
    // it came (an adapter holding our bytes back) and answers answerMs after that.
    struct DriveTiming
    {
        int holdMs = 0;
        int answerMs = 2;
        bool damaged = false; // the answer fails its check (the link asks again)
    };

    // 2-byte commands through a link that keeps 30 ms between commands, to a pty "drive"
    // that handles command k as timing[k] says; *commandAt: when the drive had each. Every
    // one is answered, and the drive has them >= 30 ms apart.
    void sendSpacedCommands(const QList<DriveTiming> &timing, QList<qint64> *commandAt)
    {
        const qsizetype count = timing.size();
        PtyEndpoint pty;
        QVERIFY(!pty.open());
        SerialLink link;
        SerialSettings s;
        s.portName = pty.clientPath();
        s.baud = 115200;
        s.minGapMs = 1;
        s.minCommandSpacingMs = 30;
        s.responseTimeoutMs = 200;
        QVERIFY(link.open(s));
        QElapsedTimer clock;
        clock.start();
        QByteArray seen;
        int came = 0;
        connect(&pty, &PtyEndpoint::received, this, [&](const QByteArray &b) {
            seen += b;
            while (seen.size() >= 2) {
                const char first = seen.at(0);
                seen.remove(0, 2);
                const DriveTiming t = timing.value(came++);
                QTimer::singleShot(t.holdMs, Qt::PreciseTimer, &pty, [&, first, t] {
                    *commandAt << clock.nsecsElapsed() / 1000;
                    QTimer::singleShot(t.answerMs, Qt::PreciseTimer, &pty,
                                       [&pty, first, t] { pty.write(reply(first, t.damaged ? DamagedValue : 1)); });
                });
            }
        });
        // A damaged answer is asked again: that retry is the next command the drive handles.
        const qsizetype requests = count
            - std::count_if(timing.begin(), timing.end(), [](const DriveTiming &t) { return t.damaged; });
        QList<LinkReply *> replies;
        for (qsizetype i = 0; i < requests; ++i) {
            SerialRequest q;
            q.bytes = QByteArray("C") + char('0' + int(i));
            q.matcher = replyOf('C');
            replies << link.send(q);
        }
        for (LinkReply *r : replies) {
            QVERIFY(waitSerial(r));
            QVERIFY2(!r->error().isError(), qPrintable(r->error().message));
        }
        QCOMPARE(commandAt->size(), count);
        for (qsizetype i = 1; i < commandAt->size(); ++i) {
            const qint64 apart = commandAt->at(i) - commandAt->at(i - 1);
            QVERIFY2(apart >= 30000, qPrintable(QString::number(apart)));
        }
    }

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
        QVERIFY(waitSerial(r));
        QVERIFY2(!r->error().isError(), qPrintable(r->error().message));
        QCOMPARE(r->frame(), reply('Q', 0x22));
    }

    // Bytes of another peer that land just before a request goes out are read and reported
    // (strayBytes), never dropped unseen: a scan learns from such a late answer that a slow
    // drive is there. Before, the link flushed the driver's input before each request, and
    // a frame landing between its last look and the flush was gone (a drive missed by
    // tst_servomodbusdrive's scan, about 1 run in 80 on a loaded machine).
    void framesOfOtherPeersAreNeverDroppedUnseen()
    {
        BusyPeerThread busy;
        BusyPeer *peer = busy.peer();
        QVERIFY(!busy.path().isEmpty());
        SerialLink link;
        SerialSettings s;
        s.portName = busy.path();
        s.baud = 115200;
        // A foreign frame read in two parts just before a request ends in what may be the
        // start of a frame: the answer that comes faster than the wire (this peer answers
        // at once) is then taken for a stale one (rule 4) and the retry takes the next.
        s.retries = 2;
        s.responseTimeoutMs = 50;
        QVERIFY(link.open(s));
        QByteArray stray;
        connect(&link, &SerialLink::strayBytes, this, [&stray](const QByteArray &b) { stray += b; });
        busy.call([peer] { return (peer->spray(true), true); });
        QElapsedTimer clock;
        clock.start();
        int answered = 0;
        for (int i = 0; clock.elapsed() < 2000; ++i) {
            SerialRequest q;
            q.bytes = QByteArray("Q") + char(i & 0x7F);
            q.matcher = replyOf('Q');
            LinkReply *r = link.send(q);
            QVERIFY(waitSerial(r));
            QVERIFY2(!r->error().isError(), qPrintable(r->error().message));
            QCOMPARE(r->frame(), reply('Q', quint8(i & 0x7F)));
            ++answered;
            r->deleteLater();
        }
        const int sent = busy.call([peer] { return (peer->spray(false), peer->sent()); });
        const QByteArray foreignHead = reply('F', 0).left(3);
        QTRY_COMPARE_WITH_TIMEOUT(int(stray.count(foreignHead)), sent, 2000);
        QVERIFY2(answered > 500 && sent > 500,
                 qPrintable(QStringLiteral("%1 requests, %2 frames").arg(answered).arg(sent)));
    }

    // A line that is never quiet (another master, a babbling drive: here a frame every
    // millisecond, and no answer) holds a retry back at most five times the quiet kept
    // after a timeout, then it goes out anyway and the request ends. Before, every byte
    // pushed the quiet on and the request never finished.
    void aLineThatIsNeverQuietStillEndsTheRequest()
    {
        BusyPeerThread busy;
        BusyPeer *peer = busy.peer();
        QVERIFY(!busy.path().isEmpty());
        busy.call([peer] { return (peer->setAnswering(false), peer->spray(true), true); });
        SerialLink link;
        TrafficTap tap;
        link.setTap(&tap);
        int notes = 0;
        LinkHealth health(115200); // as `ping`, the Link health view and the record count it
        connect(&tap, &TrafficTap::frameRecorded, this, [&notes, &health](const TrafficRecord &t) {
            notes += t.direction == TrafficRecord::Direction::Tx && t.note.contains(QStringLiteral("not quiet"));
            health.add(t);
        });
        SerialSettings s;
        s.portName = busy.path();
        s.baud = 115200;
        s.retries = 1;
        s.responseTimeoutMs = 20;
        QVERIFY(link.open(s));
        SerialRequest q;
        q.bytes = "Q1";
        q.matcher = replyOf('Q');
        QElapsedTimer clock;
        clock.start();
        LinkReply *r = link.send(q);
        QVERIFY(waitSerial(r));
        const qint64 tookMs = clock.elapsed();
        QCOMPARE(r->error().code, ErrorCode::Timeout);
        // What to do about it; not "raise the timeout" (bytes did come after it, but none answered).
        QVERIFY2(r->error().message.contains(QStringLiteral("never quiet")), qPrintable(r->error().message));
        QVERIFY2(!r->error().message.contains(QStringLiteral("raise the timeout")), qPrintable(r->error().message));
        // 2 attempts of 20 ms, the retry held back 5 x 40 ms: 240 ms, and a busy machine's slack.
        QVERIFY2(tookMs >= 220 && tookMs < 1500, qPrintable(QString::number(tookMs)));
        QCOMPARE(notes, 1); // on the retry
        QCOMPARE(health.summary().busyLineSends, 1);
        QCOMPARE(health.summary().requests, 2);
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
        QVERIFY(waitSerial(r));
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
        QList<qint64> commandAt;
        sendSpacedCommands(QList<DriveTiming>(6, DriveTiming{0, 2}), &commandAt);
        if (QTest::currentTestFailed())
            return;
        // 30 ms + the 1 ms margin + the answer's 2 ms, and timer wake-ups; under what counting
        // from the reply's end plus a second gap would give (>= 62 ms). Measured 50-52 ms while
        // other builds loaded the machine (the old bound, 45 ms, failed there every time).
        const qint64 mean = (commandAt.last() - commandAt.first()) / (commandAt.size() - 1);
        qInfo("commands %lld us apart on average", static_cast<long long>(mean));
        QVERIFY2(mean < 60000, qPrintable(QString::number(mean)));
    }

    // The count starts at the reply's first byte, with nothing taken off it. Taking off the
    // quickest turnaround seen so far (tried in session 9, to keep the drive's latency out of
    // the spacing) let a command through too soon when a drive that had answered slowly (20 ms)
    // got a command the adapter held back (10 ms) and answered it quickly (2 ms): the next
    // command came ~21 ms after it. (Under load it also failed 1 run in 20 with a steady
    // 15 ms drive, whose reads the test's event loop delayed.)
    void heldBackCommandAfterSlowAnswersStillGetsItsSpacing()
    {
        QList<qint64> commandAt;
        sendSpacedCommands({{0, 20}, {0, 20}, {0, 20}, {10, 2}, {0, 2}, {0, 2}}, &commandAt);
    }

    // A damaged answer shows as well as a good one that the drive had the command: the retry
    // is counted from its first byte too. Before, only a good answer moved the count, and a
    // retry after a command the adapter (or, in the simulator, a busy machine) held back came
    // too soon and was ignored (tst_shuokeserialascii checkByteMismatch under ASan in CI:
    // a timeout instead of the checksum error).
    void retryAfterADamagedAnswerGetsItsSpacing()
    {
        QList<qint64> commandAt;
        sendSpacedCommands({{10, 2, true}, {0, 2}, {0, 2}}, &commandAt);
    }

    // Modbus keeps 3.5 characters before a request to the drive that has just answered and
    // the full t3.5 (here 1750 us) before any other. A drive that takes the short silence
    // for part of one frame (it hears its own reply) ignores such a request: the request is
    // asked again after the full silence, and from then on every request waits the full
    // t3.5 (docs/reliability.md, "Silence between frames").
    void aDriveThatNeedsTheFullSilenceGetsItAfterOneMiss()
    {
        PtyEndpoint pty;
        QVERIFY(!pty.open());
        SerialLink link;
        TrafficTap tap;
        link.setTap(&tap);
        QStringList notes;
        connect(&tap, &TrafficTap::frameRecorded, this, [&](const TrafficRecord &rec) { notes << rec.note; });
        SerialSettings s;
        s.portName = pty.clientPath();
        s.baud = 115200;
        s.retries = 1;
        s.responseTimeoutMs = 20;
        QVERIFY(link.open(s));
        link.setInterFrameGapUs(1750);
        link.setSamePeerGapUs(304); // 3.5 characters at 115200
        QCOMPARE(link.samePeerGapUs(), 304);
        QElapsedTimer clock;
        clock.start();
        qint64 lastReplyAt = -1;
        QList<qint64> gaps; // from the drive's reply to the next request, as the drive saw it
        int ignored = 0;
        int ignoredAfterDrop = 0;
        QByteArray seen;
        connect(&pty, &PtyEndpoint::received, this, [&](const QByteArray &b) {
            seen += b;
            while (seen.size() >= 2) {
                const char first = seen.at(0);
                seen.remove(0, 2);
                const qint64 now = clock.nsecsElapsed() / 1000;
                const qint64 gap = lastReplyAt < 0 ? 1000000 : now - lastReplyAt;
                gaps << gap;
                if (gap < 1750) { // glued to its own reply: not a frame it can read
                    ++ignored;
                    if (link.samePeerGapDropped())
                        ++ignoredAfterDrop;
                    continue;
                }
                // Like a drive, 1 ms after the command (an instant answer to the retry
                // would be dropped as the late answer of the ignored request: the
                // stale-reply rule, which costs a fast peer one attempt).
                QTimer::singleShot(1, &pty, [&, first] {
                    pty.write(reply(first, 1));
                    lastReplyAt = clock.nsecsElapsed() / 1000;
                });
            }
        });
        // Until the drive has missed one (a loaded machine can stretch a short silence past
        // 1750 us now and then, so allow a few tries), then ten more.
        int sent = 0;
        for (int more = 10; sent < 40 && more > 0; ++sent) {
            SerialRequest q;
            q.bytes = QByteArray("M") + char('0' + sent % 10);
            q.matcher = replyOf('M');
            q.peer = 7;
            LinkReply *r = link.send(q);
            QVERIFY(waitSerial(r));
            QVERIFY2(!r->error().isError(), qPrintable(r->error().message));
            if (link.samePeerGapDropped())
                --more;
        }
        QVERIFY2(ignored >= 1, "no request was sent after the short silence");
        QVERIFY(link.samePeerGapDropped());
        QCOMPARE(link.samePeerGapUs(), 1750);
        QCOMPARE(ignoredAfterDrop, 0);
        QCOMPARE(link.timeoutCount(), quint64(1));
        // The trace says why the retry waited longer.
        QVERIFY2(notes.filter(QStringLiteral("the full 1750 us from now on")).size() == 1,
                 qPrintable(notes.join(QLatin1Char('\n'))));
    }

    // A request to another drive than the one that has just answered waits the full t3.5.
    void anotherDriveAlwaysGetsTheFullSilence()
    {
        PtyEndpoint pty;
        QVERIFY(!pty.open());
        SerialLink link;
        SerialSettings s;
        s.portName = pty.clientPath();
        s.baud = 115200;
        s.retries = 0;
        QVERIFY(link.open(s));
        link.setInterFrameGapUs(1750);
        link.setSamePeerGapUs(304);
        QElapsedTimer clock;
        clock.start();
        qint64 lastReplyAt = -1;
        QList<qint64> gaps;
        QByteArray seen;
        connect(&pty, &PtyEndpoint::received, this, [&](const QByteArray &b) {
            seen += b;
            while (seen.size() >= 2) {
                const char first = seen.at(0);
                seen.remove(0, 2);
                if (lastReplyAt >= 0)
                    gaps << clock.nsecsElapsed() / 1000 - lastReplyAt;
                pty.write(reply(first, 1));
                lastReplyAt = clock.nsecsElapsed() / 1000;
            }
        });
        QList<LinkReply *> replies;
        for (int i = 0; i < 10; ++i) {
            SerialRequest q;
            q.bytes = QByteArray("A") + char('0' + i);
            q.matcher = replyOf('A');
            q.peer = 1 + i % 2; // 1, 2, 1, 2, ...
            replies << link.send(q);
        }
        for (LinkReply *r : replies) {
            QVERIFY(waitSerial(r));
            QVERIFY2(!r->error().isError(), qPrintable(r->error().message));
        }
        QCOMPARE(gaps.size(), 9);
        for (qint64 g : gaps)
            QVERIFY2(g >= 1750, qPrintable(QString::number(g)));
        QVERIFY(!link.samePeerGapDropped());
    }
};

QTEST_GUILESS_MAIN(TestSerialLink)
#include "tst_seriallink.moc"
