// ModbusReplyMatcher: what in the receive buffer after a request is the reply, byte-exactly.
#include <QtTest>

#include "core/link/modbusreplymatcher.h"

using namespace dd;

namespace {
modbusrtu::Request readPa2()
{
    modbusrtu::Request q;
    q.address = 1;
    q.function = 0x03;
    q.start = 0x0066;
    q.count = 1;
    return q;
}
const QByteArray Reply = QByteArray::fromHex("0103021b9572db");         // 1: PA2 = 7061
const QByteArray OtherMaster = QByteArray::fromHex("0903000000018542"); // a master asks 9 for register 0
} // namespace

class TestModbusReplyMatcher : public QObject
{
    Q_OBJECT
private slots:
    void theReplyMatches()
    {
        const ModbusReplyMatcher m(readPa2(), QStringLiteral("ttyX"));
        const FrameMatch r = m.matcher()(Reply);
        QCOMPARE(r.status, FrameMatch::Status::Match);
        QCOMPARE(r.consumed, Reply.size());
        QCOMPARE(r.frame, Reply);
    }

    // Another master's request is its traffic, not our reply failing its CRC: passed over,
    // named in the timeout's words. Before, 8 bytes with no valid reply among them were
    // Corrupt ("failed its CRC. Check the cable shielding").
    void anotherMastersRequestIsPassedOver()
    {
        const ModbusReplyMatcher m(readPa2(), QStringLiteral("ttyX"));
        const ReplyMatcher match = m.matcher();
        FrameMatch r = match(OtherMaster);
        QCOMPARE(r.status, FrameMatch::Status::Garbage);
        QCOMPARE(r.consumed, OtherMaster.size());
        r = match(OtherMaster + Reply.left(3)); // our reply arriving behind it
        QCOMPARE(r.status, FrameMatch::Status::Garbage);
        QCOMPARE(r.consumed, OtherMaster.size());
        QCOMPARE(match(Reply).status, FrameMatch::Status::Match);
        const QString why = m.describeTimeout(50, {});
        QVERIFY2(why.contains(QStringLiteral("A frame from address 9 arrived instead")), qPrintable(why));
        QVERIFY2(why.contains(QStringLiteral("another master")), qPrintable(why));
    }

    void damagedBytesAreStillCorrupt()
    {
        const ModbusReplyMatcher m(readPa2(), QStringLiteral("ttyX"));
        QByteArray damaged = Reply;
        damaged[3] = char(damaged[3] ^ 0x01);
        const FrameMatch r = m.matcher()(damaged + QByteArray(1, '\x00'));
        QCOMPARE(r.status, FrameMatch::Status::Corrupt);
        QVERIFY(m.describeCorrupt().contains(QStringLiteral("CRC")));
    }

    // An adapter's local echo of the request comes before the reply: passed over, and not
    // named as "a frame with function 0x03 came instead" when the drive then stays silent.
    void anEchoOfTheRequestIsPassedOverSilently()
    {
        const ModbusReplyMatcher m(readPa2(), QStringLiteral("ttyX"));
        const QByteArray echo = QByteArray::fromHex("0103006600016415");
        const FrameMatch r = m.matcher()(echo);
        QCOMPARE(r.status, FrameMatch::Status::Garbage);
        QCOMPARE(r.consumed, echo.size());
        QCOMPARE(m.matcher()(echo + Reply).status, FrameMatch::Status::Garbage); // the echo first
        const QString why = m.describeTimeout(50, {});
        QVERIFY2(why.startsWith(QStringLiteral("No reply from address 1")) && !why.contains(QStringLiteral("instead")),
                 qPrintable(why));
    }
};

QTEST_GUILESS_MAIN(TestModbusReplyMatcher)
#include "tst_modbusreplymatcher.moc"
