#include <QtTest>

#include <QElapsedTimer>
#include <QSerialPort>

#include "core/link/wiretime.h"
#include "core/protocol/modbus/crc16.h"
#include "sim/bus/ptyendpoint.h"
#include "sim/bus/simserialbus.h"
#include "tests/support/requiretool.h"

#include <memory>

using namespace dd;

namespace {
constexpr int FrameSize = 8; // [addr][fc][4 data][crc lo][crc hi]

QByteArray request(quint8 addr, const QByteArray &data4)
{
    QByteArray f;
    f.append(static_cast<char>(addr));
    f.append('\x11');
    f.append(data4.left(4).leftJustified(4, '\0'));
    return withCrc16(f);
}

// A tiny drive: fixed 8-byte frames with a CRC; answers frames for its address (and the
// broadcast address 0, so that collisions can be provoked) with the same frame, function
// code | 0x80, from its own address.
class EchoDevice : public SimSerialDevice
{
public:
    EchoDevice(quint8 addr, int baud)
        : m_addr(addr)
        , m_baud(baud)
    {
    }

    QList<QByteArray> onBusBytes(const QByteArray &bytes, qint64 nowUs) override
    {
        heard += bytes;
        // resynchronise on a silence, as RTU framing does
        const double chunkUs = WireTime::serialBytesUs(bytes.size(), m_baud);
        if (lastNowUs >= 0 && nowUs - chunkUs - lastNowUs > WireTime::modbusSilenceUs(m_baud))
            m_buffer.clear();
        lastNowUs = nowUs;
        m_buffer += bytes;
        QList<QByteArray> replies;
        while (m_buffer.size() >= FrameSize) {
            const QByteArray f = m_buffer.left(FrameSize);
            m_buffer.remove(0, FrameSize);
            if (!hasValidCrc16(f) || (static_cast<quint8>(f[0]) != m_addr && f[0] != 0))
                continue;
            QByteArray r = f.left(FrameSize - 2);
            r[0] = static_cast<char>(m_addr);
            r[1] = static_cast<char>(r[1] | 0x80);
            replies << withCrc16(r);
        }
        return replies;
    }
    int baud() const override { return m_baud; }
    QString describe() const override { return QStringLiteral("echo %1 @ %2").arg(m_addr).arg(m_baud); }
    void advanceTo(qint64 nowUs) override { advancedTo = nowUs; }

    QByteArray heard;
    qint64 lastNowUs = -1;
    qint64 advancedTo = -1;

private:
    QByteArray m_buffer;
    quint8 m_addr;
    int m_baud;
};

QByteArray expectedReply(quint8 addr, const QByteArray &req)
{
    QByteArray r = req.left(FrameSize - 2);
    r[0] = static_cast<char>(addr);
    r[1] = static_cast<char>(r[1] | 0x80);
    return withCrc16(r);
}
} // namespace

class TestSimSerialBus : public QObject
{
    Q_OBJECT

    std::unique_ptr<SimSerialBus> m_bus;
    PtyEndpoint *m_pty = nullptr;
    std::unique_ptr<QSerialPort> m_client;
    QElapsedTimer m_clock;
    QList<qint64> m_arrivalsUs; // client-side time when the buffer reached n*8 bytes
    QByteArray m_rx;

    EchoDevice *addEcho(quint8 addr, int baud)
    {
        auto dev = std::make_unique<EchoDevice>(addr, baud);
        EchoDevice *raw = dev.get();
        m_bus->addDevice(std::move(dev));
        return raw;
    }

    bool openClient(int baud)
    {
        m_client = std::make_unique<QSerialPort>();
        m_client->setPortName(m_pty->slavePath());
        m_client->setBaudRate(baud);
        if (!m_client->open(QIODevice::ReadWrite))
            return false;
        connect(m_client.get(), &QSerialPort::readyRead, this, [this] {
            const qint64 t = m_clock.nsecsElapsed() / 1000;
            m_rx += m_client->readAll();
            while (m_arrivalsUs.size() < m_rx.size() / FrameSize)
                m_arrivalsUs.append(t);
        });
        return true;
    }

    // Waits for `n` reply bytes with a real event loop (QSignalSpy::wait): QTRY_ / qWait
    // sleep up to 10 ms between event-loop passes, which would blur the timing measured here.
    bool waitForBytes(int n, int timeoutMs = 2000)
    {
        QSignalSpy readyRead(m_client.get(), &QSerialPort::readyRead);
        QDeadlineTimer deadline(timeoutMs);
        while (m_rx.size() < n && !deadline.hasExpired())
            readyRead.wait(static_cast<int>(std::max<qint64>(1, deadline.remainingTime())));
        return m_rx.size() >= n;
    }

    // Sends and restarts the client-side clock just before the bytes leave.
    void send(const QByteArray &bytes)
    {
        m_rx.clear();
        m_arrivalsUs.clear();
        m_clock.start();
        QCOMPARE(m_client->write(bytes), bytes.size());
    }

private slots:
    void init()
    {
        DD_REQUIRE_TOOL(PtyEndpoint::isSupported(), "no pseudo-terminals on this system");
        auto *pty = new PtyEndpoint;
        const Error err = pty->open();
        QVERIFY2(!err, qPrintable(err.message));
        m_pty = pty;
        m_bus = std::make_unique<SimSerialBus>(pty);
        QCOMPARE(m_pty->parent(), m_bus.get());
    }
    void cleanup()
    {
        m_client.reset();
        m_bus.reset();
        m_pty = nullptr;
    }

    void replyNotBeforeWireTime_data()
    {
        QTest::addColumn<int>("baud");
        QTest::newRow("9600") << 9600;
        QTest::newRow("115200") << 115200;
    }
    void replyNotBeforeWireTime()
    {
        QFETCH(int, baud);
        EchoDevice *dev = addEcho(1, baud);
        QVERIFY(openClient(baud));
        const qint64 floorUs = static_cast<qint64>(WireTime::serialBytesUs(FrameSize, baud)) + dev->latencyUs()
            + static_cast<qint64>(WireTime::serialBytesUs(FrameSize, baud));
        for (int i = 0; i < 3; ++i) {
            const QByteArray req = request(1, QByteArray::number(i).rightJustified(4, '0'));
            send(req);
            QVERIFY(waitForBytes(FrameSize));
            QCOMPARE(m_rx.toHex(' '), expectedReply(1, req).toHex(' '));
            const qint64 took = m_arrivalsUs.first();
            qInfo("%d baud: reply after %lld us (wire-time floor %lld us)", baud, took, floorUs);
            QVERIFY2(took >= floorUs,
                     qPrintable(QStringLiteral("reply after %1 us, floor %2 us").arg(took).arg(floorUs)));
            QVERIFY2(took < floorUs + 100000, "reply far later than its wire time");
        }
        QCOMPARE(dev->heard.size(), 3 * FrameSize);
        QVERIFY(dev->advancedTo >= dev->lastNowUs);
        QCOMPARE(m_bus->stats().framesOut, 3u);
        QCOMPARE(m_bus->stats().bytesIn, quint64(3 * FrameSize));
    }

    void repliesAreSerialisedOnTheLine()
    {
        addEcho(1, 9600);
        QVERIFY(openClient(9600));
        const QByteArray a = request(1, "aaaa"), b = request(1, "bbbb");
        send(a + b);
        QVERIFY(waitForBytes(2 * FrameSize));
        QCOMPARE(m_rx, expectedReply(1, a) + expectedReply(1, b));
        const double c = WireTime::serialCharUs(9600);
        // both requests' bytes, the latency, then the replies one after the other
        QVERIFY(m_arrivalsUs.at(0) >= qint64(16 * c + 1000 + 8 * c));
        QVERIFY(m_arrivalsUs.at(1) >= qint64(16 * c + 1000 + 16 * c));
    }

    void onlyTheAddressedDriveAnswers()
    {
        EchoDevice *one = addEcho(1, 19200);
        EchoDevice *two = addEcho(2, 19200);
        QVERIFY(openClient(19200));
        const QByteArray req = request(2, "2222");
        send(req);
        QTRY_COMPARE_WITH_TIMEOUT(m_rx.size(), FrameSize, 2000);
        QCOMPARE(m_rx, expectedReply(2, req));
        QCOMPARE(one->heard, req); // every device sees every byte
        QCOMPARE(two->heard, req);
    }

    void baudMismatchGarbles()
    {
        EchoDevice *dev = addEcho(1, 9600);
        QVERIFY(openClient(19200));
        QCOMPARE(m_pty->hostBaud(), 19200);
        const QByteArray req = request(1, "baud");
        QSignalSpy readyRead(m_client.get(), &QSerialPort::readyRead);
        send(req);
        QTRY_VERIFY_WITH_TIMEOUT(!dev->heard.isEmpty(), 2000);
        QVERIFY(dev->heard != req);
        QVERIFY(!readyRead.wait(300)); // no answer to garbage
        QCOMPARE(m_bus->stats().garbledDeliveries, 1u);

        // the sweep reaches the drive's real rate: found
        dev->heard.clear();
        QVERIFY(m_client->setBaudRate(9600));
        send(req);
        QTRY_COMPARE_WITH_TIMEOUT(m_rx.size(), FrameSize, 2000);
        QCOMPARE(m_rx, expectedReply(1, req));
        QCOMPARE(dev->heard.right(FrameSize), req);
    }

    void dropAndRecover()
    {
        EchoDevice *dev = addEcho(1, 115200);
        QVERIFY(openClient(115200));
        dev->faults().setDropRate(1.0);
        QSignalSpy readyRead(m_client.get(), &QSerialPort::readyRead);
        send(request(1, "drop"));
        QTRY_COMPARE_WITH_TIMEOUT(m_bus->stats().framesDropped, 1u, 2000);
        QVERIFY(!readyRead.wait(200));
        QCOMPARE(dev->heard.size(), FrameSize); // the request was heard, the reply lost
        dev->faults().setDropRate(0.0);
        const QByteArray req = request(1, "okay");
        send(req);
        QTRY_COMPARE_WITH_TIMEOUT(m_rx.size(), FrameSize, 2000);
        QCOMPARE(m_rx, expectedReply(1, req));
    }

    void corruptFlipsOneBit()
    {
        EchoDevice *dev = addEcho(1, 115200);
        QVERIFY(openClient(115200));
        dev->faults().setCorruptRate(1.0);
        const QByteArray req = request(1, "crpt");
        send(req);
        QTRY_COMPARE_WITH_TIMEOUT(m_rx.size(), FrameSize, 2000);
        const QByteArray good = expectedReply(1, req);
        QVERIFY(!hasValidCrc16(m_rx));
        int bits = 0;
        for (int i = 0; i < FrameSize; ++i)
            bits += qPopulationCount(static_cast<quint8>(m_rx[i] ^ good[i]));
        QCOMPARE(bits, 1);
        QCOMPARE(m_bus->stats().framesCorrupted, 1u);
    }

    void extraLatencyDelays()
    {
        EchoDevice *dev = addEcho(1, 115200);
        QVERIFY(openClient(115200));
        dev->faults().setExtraLatency(80);
        send(request(1, "slow"));
        QVERIFY(waitForBytes(FrameSize));
        QVERIFY(m_arrivalsUs.first() >= 80000 + dev->latencyUs());
    }

    void silentDriveHearsAndSaysNothing()
    {
        EchoDevice *dev = addEcho(1, 38400);
        QVERIFY(openClient(38400));
        dev->faults().setSilent(true);
        QSignalSpy readyRead(m_client.get(), &QSerialPort::readyRead);
        send(request(1, "dead"));
        QTRY_COMPARE_WITH_TIMEOUT(m_bus->stats().silentDeliveries, 1u, 2000);
        QVERIFY(!readyRead.wait(200));
        QVERIFY(dev->heard.isEmpty());
        dev->faults().setSilent(false); // power back
        const QByteArray req = request(1, "live");
        send(req);
        QTRY_COMPARE_WITH_TIMEOUT(m_rx.size(), FrameSize, 2000);
        QCOMPARE(m_rx, expectedReply(1, req));
    }

    void broadcastRepliesCollide()
    {
        addEcho(1, 57600);
        addEcho(2, 57600);
        QVERIFY(openClient(57600));
        const QByteArray req = request(0, "all?");
        send(req);
        QTRY_COMPARE_WITH_TIMEOUT(m_rx.size(), FrameSize, 2000);
        QVERIFY(!hasValidCrc16(m_rx));
        QCOMPARE(m_bus->stats().collisions, 1u);
        QSignalSpy readyRead(m_client.get(), &QSerialPort::readyRead);
        QVERIFY(!readyRead.wait(100)); // one garbled frame, nothing more

        m_bus->setCollisionsModelled(false);
        send(req);
        QTRY_COMPARE_WITH_TIMEOUT(m_rx.size(), 2 * FrameSize, 2000);
        QCOMPARE(m_rx, expectedReply(1, req) + expectedReply(2, req));
    }

    void closingTheEndpointDiscardsPendingReplies()
    {
        addEcho(1, 1200); // 8 bytes take 67 ms: the reply is still pending when we close
        QVERIFY(openClient(1200));
        QSignalSpy closed(m_bus.get(), &SimSerialBus::endpointClosed);
        send(request(1, "gone"));
        QTRY_COMPARE_WITH_TIMEOUT(m_bus->pendingReplies(), 1, 2000);
        m_pty->close();
        QCOMPARE(closed.count(), 1);
        QCOMPARE(m_bus->pendingReplies(), 0);
    }
};

QTEST_GUILESS_MAIN(TestSimSerialBus)
#include "tst_simserialbus.moc"
