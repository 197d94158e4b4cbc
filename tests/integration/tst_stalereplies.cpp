// The stale-reply rule (docs/reliability.md): a stale answer is never taken for a request's
// answer, and a genuine answer is never refused because it came fast. Against peers that
// answer at once (a pty with no wire pacing, as socat pairs, Modbus slave simulators and
// deep-FIFO adapters deliver) and peers that pace their bytes like an RS485 line, for the
// SerialLink (shuoke), the ModbusLink (servo-modbus) and both families end to end.
#include <QtTest>

#include "core/drive/drivereply.h"
#include "core/drive/servomodbus/servomodbusbackend.h"
#include "core/drive/shuoke/shuokedrive.h"
#include "core/link/linkreply.h"
#include "core/link/modbuslink.h"
#include "core/link/seriallink.h"
#include "core/link/traffictap.h"
#include "core/protocol/modbus/modbusrtu.h"
#include "core/protocol/servomodbus/servomodbus.h"
#include "sim/bus/ptyendpoint.h"
#include "sim/bus/simserialbus.h"
#include "sim/servomodbus/simservomodbusdrive.h"
#include "tests/support/replywait.h"
#include "tests/support/shuokeserialbench.h"

#include <memory>

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

using namespace dd;

namespace {

// SerialLink test protocol: a reply is the request's first byte, 0xAA 0xBB, one value byte.
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

SerialRequest request(char first, int peer = 1)
{
    SerialRequest q;
    q.bytes = QByteArray(1, first) + "?";
    q.matcher = replyOf(first);
    q.expectedReplyBytes = 4;
    q.peer = peer;
    return q;
}

template <typename R>
bool wait(R *r)
{
    return test::waitInEventLoop(r, 5000);
}

// A Modbus peer on a pty that answers every read at once (no wire pacing), through
// `answer`, which may hold or rewrite the reply.
struct InstantModbusPeer
{
    PtyEndpoint pty;
    QByteArray seen;
    int requests = 0;
    std::function<void(const modbusrtu::Request &, int index)> answer;

    bool open()
    {
        if (pty.open().isError())
            return false;
        QObject::connect(&pty, &PtyEndpoint::received, &pty, [this](const QByteArray &b) {
            seen += b;
            while (seen.size() >= 8) {
                const auto r = modbusrtu::decodeRequest(seen.left(8));
                seen.remove(0, 8);
                if (r.ok())
                    answer(*r.value, requests++);
            }
        });
        return true;
    }
    static QByteArray readReply(const modbusrtu::Request &r, quint16 generation)
    {
        QList<quint16> v;
        for (int i = 0; i < r.count; ++i)
            v << quint16(r.start + i + 1000 * generation);
        return modbusrtu::encodeReadHoldingReply(r.address, v);
    }
};

// Slow enough that an instant answer is far sooner than the wire allows even when this
// machine is heavily loaded: the SerialLink tests' 2-byte request and 4-byte reply take
// 200 ms at 300 baud (a fast reply: < 100 ms); a 20-register Modbus read takes 440 ms at
// 1200 baud (< 220 ms).
constexpr int SerialBaud = 300;
constexpr int SlowBaud = 1200;

SerialSettings settings(const QString &port, int baud, int retries)
{
    SerialSettings s;
    s.portName = port;
    s.baud = baud;
    s.retries = retries;
    s.responseTimeoutMs = 30;
    return s;
}

// Frames dropped as stale while no earlier request was unanswered: a genuine reply refused.
// (A request is unanswered when the next one goes out with no reply taken for it.)
int genuineRepliesRefused(const QList<TrafficRecord> &records)
{
    int refused = 0;
    bool txSeen = false, answered = true, debt = false;
    for (const TrafficRecord &r : records) {
        switch (r.direction) {
        case TrafficRecord::Direction::Tx:
            if (txSeen && !answered)
                debt = true;
            txSeen = true;
            answered = false;
            break;
        case TrafficRecord::Direction::Rx: answered = true; break;
        default:
            if (r.note.contains(QLatin1String("stale"))) {
                refused += debt ? 0 : 1;
                debt = false;
            }
            break;
        }
    }
    return refused;
}

} // namespace

class TestStaleReplies : public QObject
{
    Q_OBJECT
private:
    // PA0..PA4 of address 7, one read each, every one answered with its register's value
    // (InstantModbusPeer::readReply, generation 0).
    static void readFiveRegisters(ModbusLink &link)
    {
        for (int i = 0; i < 5; ++i) {
            LinkReply *r = link.readHoldingRegisters(7, 0x64 + i, 1);
            QVERIFY(wait(r));
            QVERIFY2(!r->error().isError(), qPrintable(r->error().message));
            QCOMPARE(r->registers(), QList<quint16>{quint16(0x64 + i)});
        }
    }
private slots:
    void initTestCase()
    {
        if (!PtyEndpoint::isSupported())
            QSKIP("no pseudo-terminals on this system");
    }

    // The defect: a peer on a pty answers at once; the very first request of the
    // process (nothing before it could be answered) and every one after it are answered
    // sooner than the wire could carry them, and each is the genuine answer.
    void serialLinkTakesInstantAnswers()
    {
        PtyEndpoint pty;
        QVERIFY(!pty.open());
        SerialLink link;
        QVERIFY(link.open(settings(pty.clientPath(), SerialBaud, 0)));
        quint8 value = 0;
        connect(&pty, &PtyEndpoint::received, this, [&](const QByteArray &b) {
            if (b.size() == 2)
                pty.write(reply(b.at(0), ++value));
        });
        for (int i = 1; i <= 5; ++i) {
            LinkReply *r = link.send(request('A'));
            QVERIFY(wait(r));
            QVERIFY2(!r->error().isError(), qPrintable(r->error().message));
            QCOMPARE(r->frame(), reply('A', quint8(i)));
        }
        QCOMPARE(link.staleReplyCount(), quint64(0));
    }

    // A request went unanswered; its answer comes (at once) only when the next request to
    // that peer went out, followed at once by the genuine answer: the first is stale.
    void serialLinkNeverTakesTheOwedAnswer()
    {
        PtyEndpoint pty;
        QVERIFY(!pty.open());
        SerialLink link;
        QVERIFY(link.open(settings(pty.clientPath(), SerialBaud, 0)));
        int n = 0;
        connect(&pty, &PtyEndpoint::received, this, [&](const QByteArray &b) {
            if (b.size() != 2)
                return;
            if (++n == 1)
                return;                               // held back
            pty.write(reply('A', 1) + reply('A', 2)); // the late answer, then this one's
        });
        LinkReply *first = link.send(request('A'));
        LinkReply *second = link.send(request('A'));
        QVERIFY(wait(first));
        QCOMPARE(first->error().code, ErrorCode::Timeout);
        QVERIFY(wait(second));
        QVERIFY2(!second->error().isError(), qPrintable(second->error().message));
        QCOMPARE(second->frame(), reply('A', 2));
        QCOMPARE(link.staleReplyCount(), quint64(1));
    }

    // The same, but the late answer never comes and the peer answers the next request at
    // once: dropping the fast reply paid the debt, so the next attempt takes it. Another
    // peer's debt never costs this one anything.
    void serialLinkOwesOneAttemptAtMost()
    {
        PtyEndpoint pty;
        QVERIFY(!pty.open());
        SerialLink link;
        QVERIFY(link.open(settings(pty.clientPath(), SerialBaud, 2)));
        int n = 0;
        connect(&pty, &PtyEndpoint::received, this, [&](const QByteArray &b) {
            if (b.size() != 2 || ++n == 1)
                return; // the first request is lost
            pty.write(reply(b.at(0), 7));
        });
        SerialRequest lost = request('A', 1);
        lost.retries = 0;
        LinkReply *first = link.send(lost);
        QVERIFY(wait(first));
        QCOMPARE(first->error().code, ErrorCode::Timeout);
        LinkReply *other = link.send(request('B', 2));
        QVERIFY(wait(other));
        QVERIFY2(!other->error().isError(), qPrintable(other->error().message));
        QCOMPARE(other->attempts(), 1);
        LinkReply *second = link.send(request('A', 1));
        QVERIFY(wait(second));
        QVERIFY2(!second->error().isError(), qPrintable(second->error().message));
        QCOMPARE(second->frame(), reply('A', 7));
        QCOMPARE(second->attempts(), 2);
        QCOMPARE(link.staleReplyCount(), quint64(1));
    }

    // With retries 0 the message says what was seen and what to try (not "raise the timeout").
    void serialLinkSaysWhatWasDropped()
    {
        PtyEndpoint pty;
        QVERIFY(!pty.open());
        SerialLink link;
        QVERIFY(link.open(settings(pty.clientPath(), SerialBaud, 0)));
        int n = 0;
        connect(&pty, &PtyEndpoint::received, this, [&](const QByteArray &b) {
            if (b.size() == 2 && ++n > 1)
                pty.write(reply('A', 7));
        });
        LinkReply *first = link.send(request('A'));
        LinkReply *second = link.send(request('A'));
        QVERIFY(wait(first) && wait(second));
        QCOMPARE(second->error().code, ErrorCode::Timeout);
        const QString m = second->error().message;
        QVERIFY2(m.contains(QLatin1String("sooner than the wire")) && m.contains(QLatin1String("--retries")),
                 qPrintable(m));
        QVERIFY2(!m.contains(QLatin1String("raise the timeout")), qPrintable(m));
    }

    void modbusLinkTakesInstantAnswers()
    {
        InstantModbusPeer peer;
        QVERIFY(peer.open());
        peer.answer = [&](const modbusrtu::Request &r, int) { peer.pty.write(InstantModbusPeer::readReply(r, 0)); };
        ModbusLink link;
        QVERIFY(link.open(settings(peer.pty.clientPath(), 19200, 0)));
        readFiveRegisters(link);
        if (QTest::currentTestFailed())
            return;
        QCOMPARE(link.lateReplyCount(), quint64(0));
    }

    // An RS485 adapter that hears its own transmission: the request comes back at once, the
    // reply 5 ms later. Before, the echo alone was taken for a damaged reply (8 bytes, no
    // valid reply among them): a checksum error and a retry for every request, and with no
    // retries left none was ever read.
    void modbusLinkTakesTheReplyBehindAnAdapterEcho()
    {
        InstantModbusPeer peer;
        QVERIFY(peer.open());
        peer.answer = [&](const modbusrtu::Request &r, int) {
            peer.pty.write(modbusrtu::encodeRequest(r));
            QTimer::singleShot(5, &peer.pty, [&peer, r] { peer.pty.write(InstantModbusPeer::readReply(r, 0)); });
        };
        ModbusLink link;
        QVERIFY(link.open(settings(peer.pty.clientPath(), 19200, 0)));
        readFiveRegisters(link);
        if (QTest::currentTestFailed())
            return;
        QCOMPARE(peer.requests, 5);
    }

    // Modbus: the answer owed to a timed-out request arrives at once after the next
    // request to that address, the genuine one right behind it.
    void modbusLinkNeverTakesTheOwedAnswer()
    {
        InstantModbusPeer peer;
        QVERIFY(peer.open());
        QByteArray held;
        peer.answer = [&](const modbusrtu::Request &r, int index) {
            if (index == 0) {
                held = InstantModbusPeer::readReply(r, 0);
                return;
            }
            peer.pty.write(held + InstantModbusPeer::readReply(r, 1));
            held.clear();
        };
        ModbusLink link;
        QVERIFY(link.open(settings(peer.pty.clientPath(), SlowBaud, 2)));
        ModbusRequest q;
        q.pdu = {7, modbusrtu::ReadHoldingRegisters, 0x64, 20, {}};
        q.retries = 0;
        LinkReply *first = link.send(q);
        LinkReply *second = link.readHoldingRegisters(7, 0x64, 20);
        QVERIFY(wait(first));
        QCOMPARE(first->error().code, ErrorCode::Timeout);
        QVERIFY(wait(second));
        QVERIFY2(!second->error().isError(), qPrintable(second->error().message));
        QCOMPARE(second->registers().value(0), quint16(0x64 + 1000));
    }

    // Another address's late answer lands while a request waits, and that request's reply
    // follows: the link passes over the first frame and reports it as stray (a scan asks
    // that address again) instead of losing it with the transaction.
    void modbusLinkReportsALateAnswerThatCameWithAReply()
    {
        InstantModbusPeer peer;
        QVERIFY(peer.open());
        modbusrtu::Request other{5, modbusrtu::ReadHoldingRegisters, 0x66, 1, {}};
        const QByteArray late = InstantModbusPeer::readReply(other, 0);
        peer.answer = [&](const modbusrtu::Request &r, int) {
            peer.pty.write(late);
            QTimer::singleShot(5, &peer.pty, [&peer, r] { peer.pty.write(InstantModbusPeer::readReply(r, 1)); });
        };
        ModbusLink link;
        QVERIFY(link.open(settings(peer.pty.clientPath(), 19200, 0)));
        QByteArray stray;
        connect(&link, &ModbusLink::strayBytes, this, [&](const QByteArray &b) { stray += b; });
        LinkReply *r = link.readHoldingRegisters(7, 0x64, 1);
        QVERIFY(wait(r));
        QVERIFY2(!r->error().isError(), qPrintable(r->error().message));
        QCOMPARE(r->registers(), QList<quint16>{quint16(0x64 + 1000)});
        QTRY_COMPARE_WITH_TIMEOUT(stray, late, 2000);
    }

    // Bytes that wait unread at the port when a request goes out (a late answer that came
    // while no event was processed) answer no request: the link flushes them, but shows
    // them as stray first, so that a scan still asks that address again; being another
    // address's answer, they do not make this request's fast reply stale.
    void modbusLinkReportsUnreadBytesItFlushes()
    {
        InstantModbusPeer peer;
        QVERIFY(peer.open());
        peer.answer = [&](const modbusrtu::Request &r, int) { peer.pty.write(InstantModbusPeer::readReply(r, 0)); };
        ModbusLink link;
        QVERIFY(link.open(settings(peer.pty.clientPath(), 19200, 0)));
        QByteArray stray;
        connect(&link, &ModbusLink::strayBytes, this, [&](const QByteArray &b) { stray += b; });
        const QByteArray late = InstantModbusPeer::readReply({5, modbusrtu::ReadHoldingRegisters, 0x66, 1, {}}, 0);
        // Until the request goes out no event is processed, so the link does not read them: a
        // second descriptor of the same pty shows when they wait at the port.
        const int fd = ::open(QFile::encodeName(peer.pty.clientPath()).constData(), O_RDONLY | O_NOCTTY | O_NONBLOCK);
        QVERIFY(fd >= 0);
        QCOMPARE(peer.pty.write(late), qint64(late.size()));
        pollfd p{fd, POLLIN, 0};
        const int ready = ::poll(&p, 1, 5000);
        ::close(fd);
        QCOMPARE(ready, 1);
        LinkReply *r = link.readHoldingRegisters(7, 0x64, 1);
        QVERIFY(wait(r));
        QVERIFY2(!r->error().isError(), qPrintable(r->error().message));
        QTRY_COMPARE_WITH_TIMEOUT(stray, late, 2000);
    }

    // End to end, both serial families (servo-modbus with retries 0, so a genuine reply
    // refused fails the read): a drive on a line that paces its bytes and one that answers
    // at once. No frame is dropped as stale unless an earlier request went unanswered.
    void familiesOnPacedAndInstantPeers_data()
    {
        QTest::addColumn<bool>("paced");
        QTest::addColumn<int>("baud");
        QTest::newRow("paced 115200") << true << 115200;
        QTest::newRow("paced 9600") << true << 9600;
        QTest::newRow("instant 115200") << false << 115200;
        QTest::newRow("instant 9600") << false << 9600;
    }
    void familiesOnPacedAndInstantPeers()
    {
        QFETCH(bool, paced);
        QFETCH(int, baud);
        servoModbus(paced, baud);
        if (QTest::currentTestFailed())
            return;
        shuokeRtu(paced, 9600); // the simulated drive's baud code 6
    }

private:
    void servoModbus(bool paced, int baud)
    {
        auto *pty = new PtyEndpoint;
        QVERIFY(!pty->open());
        SimSerialBus bus(pty);
        bus.setWirePaced(paced);
        SimServoModbusDrive::Config c;
        c.address = 7;
        c.baud = baud;
        bus.addDevice(std::make_unique<SimServoModbusDrive>(c));
        TrafficTap tap;
        QList<TrafficRecord> records;
        connect(&tap, &TrafficTap::frameRecorded, this, [&](const TrafficRecord &r) { records << r; });
        ServoModbusBackend backend;
        ConnectionSettings cs;
        cs.family = Family::ServoModbus;
        cs.port = pty->clientPath();
        cs.baud = baud;
        cs.retries = 0;
        Error e;
        QVERIFY2(backend.open(cs, &tap, &e), qPrintable(e.message));
        Drive *d = backend.drive(7);
        DriveReply *id = d->refreshIdentity();
        QVERIFY(wait(id));
        QVERIFY2(!id->error().isError(), qPrintable(id->error().message));
        QList<int> all;
        for (int n = 0; n < servomodbus::ParameterCount; ++n)
            all << n;
        for (int round = 0; round < 3; ++round) {
            DriveReply *r = d->readParameters(all);
            QVERIFY(wait(r));
            QVERIFY2(!r->error().isError(), qPrintable(r->error().message));
            QCOMPARE(r->parameters().size(), servomodbus::ParameterCount);
        }
        QCOMPARE(genuineRepliesRefused(records), 0);
        backend.close();
    }

    void shuokeRtu(bool paced, int baud)
    {
        ShuokeSerialBench bench;
        QString why;
        QVERIFY2(bench.start(&why), qPrintable(why));
        bench.bus()->setWirePaced(paced);
        SimShuokeDrive::Config c;
        c.address = 1;
        c.powerUpWindowMs = 0;
        bench.addDrive(c);
        ConnectionSettings s;
        s.framing = QStringLiteral("rtu");
        s.baud = baud;
        // The simulated drive, in this thread, may read a command late and then find the
        // next one closer than its 50 ms and ignore it; on an instant line the retry's fast
        // answer is then dropped once as that command's late answer (the rule), so two.
        s.retries = 2;
        QVERIFY2(bench.connectHost(s, &why), qPrintable(why)); // the 0x20 handshake
        ShuokeDrive *d = bench.drive(1);
        QVERIFY(d);
        DriveReply *r = d->readParameters({36, 37, 39, 41, 43, 45, 47, 95, 97});
        QVERIFY(ShuokeSerialBench::wait(r));
        QVERIFY2(!r->error().isError(), qPrintable(r->error().message));
        QCOMPARE(genuineRepliesRefused(bench.records()), 0);
    }
};

QTEST_GUILESS_MAIN(TestStaleReplies)
#include "tst_stalereplies.moc"
