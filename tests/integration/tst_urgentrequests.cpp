// Urgent requests (stops, disables) on every link: with ordinary requests queued, an urgent
// one goes out right after the transaction on the wire, ahead of every waiting ordinary
// one, urgent ones in the order they came; the one on the wire is never aborted.
//  - SerialLink over a pty against an echoing peer;
//  - ModbusLink (on SerialLink) over a pty against a Modbus server;
//  - CanLink on a private virtualcan hub against an answering CanLink.
// The order is checked on the wire (what the peer received) and in the TrafficTap.

#include "core/link/canlink.h"
#include "core/link/modbuslink.h"
#include "core/link/seriallink.h"
#include "core/link/traffictap.h"
#include "core/protocol/modbus/modbusrtu.h"
#include "core/protocol/modbus/modbusrtuparser.h"
#include "sim/bus/ptyendpoint.h"
#include "sim/bus/virtualcanhub.h"
#include "tests/support/requiretool.h"

#include <QSignalSpy>
#include <QTimer>
#include <QtTest>

using namespace dd;

namespace {

// Runs a real event loop until every reply has finished (or `ms` pass).
bool waitAll(const QList<LinkReply *> &replies, int ms = 5000)
{
    QElapsedTimer t;
    t.start();
    for (LinkReply *r : replies) {
        while (!r->isFinished() && t.elapsed() < ms) {
            QSignalSpy done(r, &LinkReply::finished);
            done.wait(int(std::max<qint64>(1, ms - t.elapsed())));
        }
        if (!r->isFinished())
            return false;
    }
    return true;
}

QList<QByteArray> txOf(const QList<TrafficRecord> &records)
{
    QList<QByteArray> tx;
    for (const TrafficRecord &r : records)
        if (r.direction == TrafficRecord::Direction::Tx)
            tx << r.bytes;
    return tx;
}

// Serial requests are 2 bytes ("A1", "U1", ...); the peer echoes each after `delayMs`.
SerialRequest echoRequest(const QByteArray &bytes, bool urgent)
{
    SerialRequest r;
    r.bytes = bytes;
    r.expectedReplyBytes = int(bytes.size());
    r.urgent = urgent;
    r.matcher = [bytes](const QByteArray &buffer) {
        if (buffer.size() < bytes.size())
            return FrameMatch::incomplete();
        return buffer.startsWith(bytes) ? FrameMatch::match(bytes.size(), bytes) : FrameMatch::garbage(1);
    };
    return r;
}

} // namespace

class TestUrgentRequests : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void serialLinkSendsUrgentRightAfterTheOneOnTheWire();
    void modbusLinkSendsUrgentRightAfterTheOneInFlight();
    void canLinkUrgentGoesAheadOfTheWindowQueue();
};

void TestUrgentRequests::initTestCase()
{
    DD_REQUIRE_TOOL(PtyEndpoint::isSupported(), "no pseudo-terminals on this platform");
}

void TestUrgentRequests::serialLinkSendsUrgentRightAfterTheOneOnTheWire()
{
    PtyEndpoint peer;
    QVERIFY(!peer.open().isError());
    QList<QByteArray> heard;
    QByteArray pending;
    connect(&peer, &ByteEndpoint::received, this, [&](const QByteArray &bytes) {
        pending += bytes;
        while (pending.size() >= 2) {
            const QByteArray frame = pending.left(2);
            pending.remove(0, 2);
            heard << frame;
            QTimer::singleShot(20, Qt::PreciseTimer, &peer, [&peer, frame] { peer.write(frame); });
        }
    });
    TrafficTap tap;
    QList<TrafficRecord> records;
    connect(&tap, &TrafficTap::frameRecorded, this, [&](const TrafficRecord &r) { records << r; });
    SerialLink link;
    link.setTap(&tap);
    SerialSettings s;
    s.portName = peer.clientPath();
    s.baud = 115200;
    s.retries = 0;
    s.responseTimeoutMs = 500;
    s.minGapMs = 2;
    Error e;
    QVERIFY2(link.open(s, &e), qPrintable(e.message));

    QList<LinkReply *> replies;
    replies << link.send(echoRequest("A1", false)); // on the wire at once
    replies << link.send(echoRequest("A2", false));
    replies << link.send(echoRequest("A3", false));
    replies << link.send(echoRequest("U1", true));
    replies << link.send(echoRequest("A4", false));
    replies << link.send(echoRequest("U2", true));
    QCOMPARE(link.queuedCount(), 6);
    QVERIFY(waitAll(replies));
    for (LinkReply *r : replies)
        QVERIFY2(!r->error(), qPrintable(r->error().message));
    const QList<QByteArray> expected{"A1", "U1", "U2", "A2", "A3", "A4"};
    QCOMPARE(heard, expected);
    QCOMPARE(txOf(records), expected);
    // Every reply is its own request's (the one on the wire was not aborted).
    const QList<QByteArray> asked{"A1", "A2", "A3", "U1", "A4", "U2"};
    for (int i = 0; i < replies.size(); ++i)
        QCOMPARE(replies.at(i)->frame(), asked.at(i));
}

void TestUrgentRequests::modbusLinkSendsUrgentRightAfterTheOneInFlight()
{
    PtyEndpoint peer;
    QVERIFY(!peer.open().isError());
    QList<modbusrtu::Request> heard;
    ModbusRtuStreamParser parser{ModbusRtuStreamParser::Mode::Requests};
    connect(&peer, &ByteEndpoint::received, this, [&](const QByteArray &bytes) {
        parser.feed(bytes);
        while (parser.hasFrame()) {
            const auto d = modbusrtu::decodeRequest(parser.takeFrame());
            if (!d.ok())
                continue;
            const modbusrtu::Request req = *d.value;
            heard << req;
            const QByteArray reply = req.function == modbusrtu::WriteSingleRegister
                ? modbusrtu::encodeWriteSingleReply(req.address, req.start, req.values.value(0))
                : modbusrtu::encodeReadHoldingReply(req.address, QList<quint16>(req.count, req.start));
            QTimer::singleShot(20, Qt::PreciseTimer, &peer, [&peer, reply] { peer.write(reply); });
        }
    });
    ModbusLink link;
    SerialSettings s;
    s.portName = peer.clientPath();
    s.baud = 115200;
    s.retries = 0;
    s.responseTimeoutMs = 500;
    Error e;
    QVERIFY2(link.open(s, &e), qPrintable(e.message));

    auto read = [&](int start) { return link.readHoldingRegisters(1, start, 1); };
    auto urgentWrite = [&](int reg) {
        ModbusRequest r;
        r.pdu.address = 1;
        r.pdu.function = modbusrtu::WriteSingleRegister;
        r.pdu.start = quint16(reg);
        r.pdu.values = {0};
        r.urgent = true;
        return link.send(r);
    };
    QList<LinkReply *> replies;
    replies << read(0x10) << read(0x11) << read(0x12) << urgentWrite(0x20) << read(0x13) << urgentWrite(0x21);
    QVERIFY(waitAll(replies));
    for (LinkReply *r : replies)
        QVERIFY2(!r->error(), qPrintable(r->error().message));
    QList<int> order;
    for (const modbusrtu::Request &r : std::as_const(heard))
        order << r.start;
    QCOMPARE(order, (QList<int>{0x10, 0x20, 0x21, 0x11, 0x12, 0x13}));
    QCOMPARE(replies.at(1)->registers(), QList<quint16>{0x11}); // each got its own answer
    QCOMPARE(replies.at(3)->registers(), (QList<quint16>{0x20, 0}));
}

void TestUrgentRequests::canLinkUrgentGoesAheadOfTheWindowQueue()
{
    VirtualCanHub hub;
    QVERIFY(hub.start());
    CanSettings cs;
    cs.plugin = QStringLiteral("virtualcan");
    cs.interface = hub.interfaceName(1);
    cs.maxInFlight = 1; // one request on the bus at a time: the rest wait in the queue
    cs.retries = 0;
    cs.responseTimeoutMs = 1000;
    // The peer answers request id 0x100 + n with id 0x200 + n, 20 ms later.
    CanLink peer;
    QList<quint32> heard;
    connect(&peer, &CanLink::frameReceived, this, [&](const CanFrameData &f) {
        heard << f.id;
        if (f.id >= 0x100 && f.id < 0x180)
            QTimer::singleShot(20, Qt::PreciseTimer, &peer, [&peer, f] {
                peer.send(CanFrameData{f.id + 0x100, f.data, false});
            });
    });
    Error e;
    QVERIFY2(peer.open(cs, &e), qPrintable(e.message));
    TrafficTap tap;
    QList<TrafficRecord> records;
    connect(&tap, &TrafficTap::frameRecorded, this, [&](const TrafficRecord &r) { records << r; });
    CanLink link;
    link.setTap(&tap);
    QVERIFY2(link.open(cs, &e), qPrintable(e.message));
    QSignalSpy peerUp(&peer, &CanLink::connected);
    QSignalSpy linkUp(&link, &CanLink::connected);
    QVERIFY(peer.isConnected() || peerUp.wait(5000));
    QVERIFY(link.isConnected() || linkUp.wait(5000));
    VirtualCanHub::setLowDelay(&peer);
    VirtualCanHub::setLowDelay(&link);

    auto request = [&](quint32 n, bool urgent, bool answered) {
        CanRequest r;
        r.frame = CanFrameData{0x100 + n, QByteArray(1, char(n)), false};
        if (answered)
            r.matcher = [n](const CanFrameData &f) { return f.id == 0x200 + n; };
        r.urgent = urgent;
        return link.request(r);
    };
    QList<LinkReply *> replies;
    replies << request(1, false, true) // in flight at once
            << request(2, false, true) << request(3, false, true)
            << request(0x12, true, false) // urgent, unanswered: takes no place, goes at once
            << request(0x11, true, true)  // urgent, answered: the next one in the window
            << request(4, false, true);
    QVERIFY(waitAll(replies));
    for (LinkReply *r : replies)
        QVERIFY2(!r->error(), qPrintable(r->error().message));
    QList<quint32> tx;
    for (const TrafficRecord &r : std::as_const(records))
        if (r.direction == TrafficRecord::Direction::Tx)
            tx << r.canId;
    const QList<quint32> expected{0x101, 0x112, 0x111, 0x102, 0x103, 0x104};
    QCOMPARE(tx, expected);
    QCOMPARE(heard, expected);
}

QTEST_GUILESS_MAIN(TestUrgentRequests)
#include "tst_urgentrequests.moc"
