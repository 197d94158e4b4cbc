// LinkHealth: the link's health of one drive from the traffic records alone.
#include <QtTest>

#include "core/link/linkhealth.h"

using namespace dd;

namespace {
TrafficRecord rec(qint64 atUs, TrafficRecord::Direction d, const QByteArray &hex, const QString &note = {})
{
    TrafficRecord r;
    r.timestampUs = atUs;
    r.direction = d;
    r.bytes = QByteArray::fromHex(hex);
    r.note = note;
    return r;
}
constexpr auto Tx = TrafficRecord::Direction::Tx;
constexpr auto Rx = TrafficRecord::Direction::Rx;
constexpr auto Drop = TrafficRecord::Direction::Discarded;
} // namespace

class TestLinkHealth : public QObject
{
    Q_OBJECT
private slots:
    void turnaroundsAndCounts()
    {
        LinkHealth h(115200);
        h.setAddress(7);
        const QByteArray req = "0703006600016473";
        const QByteArray rep = "0703021b95fadb";
        h.add(rec(0, Tx, req));
        h.add(rec(2000, Rx, rep)); // 2 ms
        h.add(rec(10000, Tx, req));
        h.add(rec(11000, Rx, rep)); // 1 ms
        h.add(rec(20000, Tx, req));
        h.add(rec(26000, Rx, rep)); // 6 ms
        h.add(rec(30000, Tx, req)); // unanswered: timeout
        h.add(rec(60000, Tx, req, QStringLiteral("(retry 1)")));
        h.add(rec(60500, Drop, rep, QStringLiteral("bad checksum"))); // checksum error
        h.add(rec(90000, Tx, req, QStringLiteral("(retry 2) (the line was not quiet for 500 ms: sent anyway)")));
        h.add(rec(90100, Drop, rep, QStringLiteral("stale: came 100 us after the request")));
        h.add(rec(92000, Rx, rep));                // 2 ms
        h.add(rec(93000, Tx, "0103006600016473")); // another drive
        h.add(rec(93500, Rx, "0103021b95fadb"));
        const LinkHealth::Summary s = h.summary();
        QCOMPARE(s.requests, 6);
        QCOMPARE(s.answered, 4);
        QCOMPARE(s.timeouts, 1);
        QCOMPARE(s.checksumErrors, 1);
        QCOMPARE(s.lateReplies, 1);
        QCOMPARE(s.retries, 2);
        QCOMPARE(s.busyLineSends, 1);
        QCOMPARE(s.minMs, 1.0);
        QCOMPARE(s.medianMs, 2.0);
        QCOMPARE(s.maxMs, 6.0);
        // 8 + 7 bytes at 115200: 1.302 ms of wire; 2 x (6 - 1.302) = 9.4 -> at least 10 ms.
        QCOMPARE(s.recommendedTimeoutMs, 10);
        QCOMPARE(s.recommendedGapMs, 6); // late replies seen: let them land first
    }

    void healthyLinkNeedsNoGap()
    {
        LinkHealth h(9600);
        for (int i = 0; i < 3; ++i) {
            h.add(rec(i * 100000, Tx, "0503006400149e05"));
            h.add(rec(i * 100000 + 60000, Rx, "0503"));
        }
        const LinkHealth::Summary s = h.summary();
        QCOMPARE(s.answered, 3);
        QCOMPARE(s.timeouts, 0);
        QCOMPARE(s.recommendedGapMs, 0);
        // 8 + 2 bytes at 9600: 10.4 ms of wire; 2 x (60 - 10.4) = 99.2 -> 100 ms.
        QCOMPARE(s.recommendedTimeoutMs, 100);
    }

    // CAN: three reads pipelined, answered together; a heartbeat and a keep-alive between;
    // a read asked again (its first answer lost) counts as a timeout.
    void pipelinedCanReads()
    {
        auto can = [](qint64 at, TrafficRecord::Direction d, const QByteArray &hex, const QString &note = {}) {
            TrafficRecord r = rec(at, d, hex, note);
            r.isCan = true;
            r.canId = 0x65;
            return r;
        };
        LinkHealth h;
        h.setAddress(1);
        h.add(can(0, Tx, "0112fd00000000ff"));
        h.add(can(10, Tx, "0112fc00000000ff"));
        h.add(can(20, Tx, "0112aa00000000ff"));
        h.add(can(1000, Rx, "0110880000000ff0", {})); // heartbeat
        h.add(can(1100, Tx, "0108000000000000", QStringLiteral("(keep-alive)")));
        h.add(can(2000, Rx, "0112fd00000000ff"));
        h.add(can(3010, Rx, "0112fc00000000ff"));
        h.add(can(50000, Tx, "0112aa00000000ff", QStringLiteral("(retry 1)")));
        h.add(can(54000, Rx, "0112aa00000000ff"));
        h.add(can(55000, Tx, "0212fd00000000ff")); // station 2
        const LinkHealth::Summary s = h.summary();
        QCOMPARE(s.requests, 4);
        QCOMPARE(s.answered, 3);
        QCOMPARE(s.timeouts, 1);
        QCOMPARE(s.retries, 1);
        QCOMPARE(s.minMs, 2.0);
        QCOMPARE(s.medianMs, 3.0);
        QCOMPARE(s.maxMs, 4.0);
    }

    void broadcastsAreNotRequests()
    {
        LinkHealth h(19200);
        h.add(rec(0, Tx, "00060000000189db"));
        h.add(rec(5000, Tx, "0103006600016473"));
        h.add(rec(7000, Rx, "0103021b95fadb"));
        QCOMPARE(h.summary().requests, 1);
        QCOMPARE(h.summary().timeouts, 0);
    }

    // A request still out is not counted while its answer may be on its way; once the
    // sender has waited for every request (ping, the CLI's record) it timed out. Before,
    // `ping` against a silent drive said 3 timeouts for 4 requests that all timed out.
    void requestsStillOutAtTheEndTimedOut()
    {
        LinkHealth serial(115200);
        serial.add(rec(0, Tx, "0103006600016473"));
        serial.add(rec(20000, Tx, "0103006600016473", QStringLiteral("(retry 1)")));
        serial.add(rec(30000, Drop, "0103021b95fadc", QStringLiteral("bad checksum")));
        QCOMPARE(serial.summary().timeouts, 1);
        QCOMPARE(serial.summary().checksumErrors, 0);
        serial.closeOutstanding();
        QCOMPARE(serial.summary().timeouts, 1);
        QCOMPARE(serial.summary().checksumErrors, 1);
        serial.closeOutstanding(); // nothing is out now
        QCOMPARE(serial.summary().timeouts + serial.summary().checksumErrors, 2);

        LinkHealth can;
        for (const char *hex : {"0112fd00000000ff", "0112fc00000000ff"}) {
            TrafficRecord r = rec(0, Tx, hex);
            r.isCan = true;
            can.add(r);
        }
        QCOMPARE(can.summary().timeouts, 0);
        can.closeOutstanding();
        QCOMPARE(can.summary().timeouts, 2);
        QCOMPARE(can.summary().requests, 2);
    }
};

QTEST_GUILESS_MAIN(TestLinkHealth)
#include "tst_linkhealth.moc"
