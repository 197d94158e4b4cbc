// View → Link health: per drive, from the traffic seen (LinkHealthDock).
#include <QtTest>

#include "ui/linkhealth/linkhealthdock.h"

#include <QTableWidget>

using namespace dd;

namespace {
TrafficRecord rec(qint64 atUs, TrafficRecord::Direction d, const QByteArray &hex, const QString &note = {})
{
    TrafficRecord r;
    r.timestampUs = atUs;
    r.direction = d;
    r.link = QStringLiteral("/dev/ttyUSB0");
    r.bytes = QByteArray::fromHex(hex);
    r.note = note;
    return r;
}
constexpr auto Tx = TrafficRecord::Direction::Tx;
constexpr auto Rx = TrafficRecord::Direction::Rx;
} // namespace

class TestLinkHealthDock : public QObject
{
    Q_OBJECT
private slots:
    void oneRowPerDrive()
    {
        LinkHealthDock dock(nullptr);
        // Drive 7 answers in 2 and 4 ms; drive 3 once in 1 ms, then not at all.
        dock.addTraffic(1, rec(0, Tx, "0703006600016473"));
        dock.addTraffic(1, rec(2000, Rx, "0703021b95fadb"));
        dock.addTraffic(1, rec(5000, Tx, "0303006600016473"));
        dock.addTraffic(1, rec(6000, Rx, "0303021b95fadb"));
        dock.addTraffic(1, rec(10000, Tx, "0703006600016473"));
        dock.addTraffic(1, rec(14000, Rx, "0703021b95fadb"));
        dock.addTraffic(1, rec(20000, Tx, "0303006600016473"));
        dock.addTraffic(1,
                        rec(80000, Tx, "0303006600016473",
                            QStringLiteral("(retry 1) (the line was not quiet for 500 ms: sent anyway)")));
        dock.addTraffic(1, rec(81000, Rx, "0303021b95fadb"));
        dock.refresh();
        QTableWidget *t = dock.table();
        QCOMPARE(t->rowCount(), 2);
        QCOMPARE(t->item(0, 0)->text(), QStringLiteral("/dev/ttyUSB0, address 3"));
        QCOMPARE(t->item(1, 0)->text(), QStringLiteral("/dev/ttyUSB0, address 7"));
        QCOMPARE(t->item(1, 3)->text(), QStringLiteral("2.0 / 3.0 / 4.0 ms"));
        const LinkHealth::Summary three = dock.summary(1, 3);
        QCOMPARE(three.requests, 3);
        QCOMPARE(three.answered, 2);
        QCOMPARE(three.timeouts, 1);
        QCOMPARE(three.retries, 1);
        QCOMPARE(t->item(0, 4)->text(), QStringLiteral("1"));
        QCOMPARE(three.busyLineSends, 1);
        QCOMPARE(t->horizontalHeaderItem(8)->text(), QStringLiteral("Sent on a busy line"));
        QCOMPARE(t->item(0, 8)->text(), QStringLiteral("1"));
        QCOMPARE(t->item(1, 8)->text(), QStringLiteral("0"));
        dock.clear();
        QCOMPARE(t->rowCount(), 0);
    }
};

QTEST_MAIN(TestLinkHealthDock)
#include "tst_linkhealthdock.moc"
