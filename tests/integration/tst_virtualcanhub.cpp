// VirtualCanHub as a bus: the plugin's line protocol between clients, the in-process device
// the simulator attaches with (HubCanDevice: frames as calls, no socket), and frames sent
// while a client's "connect:" line is still on the way.

#include "sim/bus/virtualcanhub.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QSignalSpy>
#include <QTcpSocket>
#include <QTest>

#include <memory>

using namespace dd;

namespace {
std::unique_ptr<QCanBusDevice> pluginClient(const VirtualCanHub &hub, int channel)
{
    std::unique_ptr<QCanBusDevice> d(
        QCanBus::instance()->createDevice(QStringLiteral("virtualcan"), hub.interfaceName(channel)));
    if (!d || !d->connectDevice())
        return nullptr;
    if (d->state() != QCanBusDevice::ConnectedState) {
        QSignalSpy up(d.get(), &QCanBusDevice::stateChanged);
        while (d->state() != QCanBusDevice::ConnectedState && up.wait(5000)) {
        }
    }
    VirtualCanHub::setLowDelay(d.get());
    return d->state() == QCanBusDevice::ConnectedState ? std::move(d) : nullptr;
}

// Every frame `device` receives within `ms`, until `count` came.
QList<QCanBusFrame> receive(QCanBusDevice *device, int count, int ms = 3000)
{
    QList<QCanBusFrame> frames;
    QElapsedTimer t;
    t.start();
    while (frames.size() < count && t.elapsed() < ms) {
        QTest::qWait(5);
        frames += device->readAllFrames();
    }
    return frames;
}

std::unique_ptr<QCanBusDevice> localDevice(VirtualCanHub &hub, int channel)
{
    std::unique_ptr<QCanBusDevice> d(hub.createLocalDevice(channel));
    if (!d->connectDevice() || d->state() != QCanBusDevice::ConnectedState)
        return nullptr;
    return d;
}
} // namespace

class TestVirtualCanHub : public QObject
{
    Q_OBJECT
private slots:
    void localDeviceAndPluginClientExchangeFrames();
    void channelsStayApart();
    void framesBeforeAClientsConnectLineReachIt();
    void badLinesReachNobody();
    void localDeviceNeedsARunningHub();
};

void TestVirtualCanHub::localDeviceAndPluginClientExchangeFrames()
{
    VirtualCanHub hub;
    QVERIFY(hub.start());
    auto local = localDevice(hub, 0);
    QVERIFY(local);
    auto client = pluginClient(hub, 0);
    QVERIFY(client);

    // Client -> local: standard and extended identifiers, empty and full payloads.
    QCanBusFrame a(0x601, QByteArray::fromHex("4000100000000000"));
    QCanBusFrame b(0x18FF50E5, QByteArray::fromHex("01"));
    b.setExtendedFrameFormat(true);
    QCanBusFrame c(0x7FF, QByteArray());
    QVERIFY(client->writeFrame(a) && client->writeFrame(b) && client->writeFrame(c));
    const QList<QCanBusFrame> atLocal = receive(local.get(), 3);
    QCOMPARE(atLocal.size(), 3);
    QCOMPARE(atLocal.at(0).frameId(), 0x601u);
    QCOMPARE(atLocal.at(0).payload().toHex(), QByteArray("4000100000000000"));
    QVERIFY(!atLocal.at(0).hasExtendedFrameFormat());
    QCOMPARE(atLocal.at(1).frameId(), 0x18FF50E5u);
    QVERIFY(atLocal.at(1).hasExtendedFrameFormat());
    QCOMPARE(atLocal.at(1).payload().toHex(), QByteArray("01"));
    QCOMPARE(atLocal.at(2).frameId(), 0x7FFu);
    QVERIFY(atLocal.at(2).payload().isEmpty());

    // Local -> client, the same way back.
    QCanBusFrame d(0x581, QByteArray::fromHex("4b00100012340000"));
    QCanBusFrame e(0x1ABCDEF0, QByteArray::fromHex("aabb"));
    e.setExtendedFrameFormat(true);
    QVERIFY(local->writeFrame(d) && local->writeFrame(e));
    const QList<QCanBusFrame> atClient = receive(client.get(), 2);
    QCOMPARE(atClient.size(), 2);
    QCOMPARE(atClient.at(0).frameId(), 0x581u);
    QCOMPARE(atClient.at(0).payload().toHex(), QByteArray("4b00100012340000"));
    QCOMPARE(atClient.at(1).frameId(), 0x1ABCDEF0u);
    QVERIFY(atClient.at(1).hasExtendedFrameFormat());
    QCOMPARE(atClient.at(1).payload().toHex(), QByteArray("aabb"));
    // A device does not hear itself.
    QVERIFY(local->readAllFrames().isEmpty());
}

void TestVirtualCanHub::channelsStayApart()
{
    VirtualCanHub hub;
    QVERIFY(hub.start());
    auto local0 = localDevice(hub, 0);
    auto local1 = localDevice(hub, 1);
    QVERIFY(local0 && local1);
    auto client1 = pluginClient(hub, 1);
    QVERIFY(client1);
    QVERIFY(client1->writeFrame(QCanBusFrame(0x123, QByteArray::fromHex("11"))));
    QCOMPARE(receive(local1.get(), 1).size(), 1);
    QVERIFY(local0->readAllFrames().isEmpty());
    QVERIFY(local0->writeFrame(QCanBusFrame(0x124, QByteArray::fromHex("22"))));
    QTest::qWait(50);
    QVERIFY(client1->readAllFrames().isEmpty());
    QVERIFY(local1->readAllFrames().isEmpty());
}

void TestVirtualCanHub::framesBeforeAClientsConnectLineReachIt()
{
    // A plugin client counts as connected once its socket is, before the hub has read its
    // "connect:canN" line: frames sent on the bus meanwhile must still reach it (they were
    // lost, and a request sent right after both links came up went unanswered).
    VirtualCanHub hub;
    QVERIFY(hub.start());
    auto local = localDevice(hub, 1);
    QVERIFY(local);
    QTcpSocket late;
    late.connectToHost(QHostAddress::LocalHost, hub.port());
    QVERIFY(late.waitForConnected(5000));
    QTRY_COMPARE(hub.clientCount(), 1); // accepted, no channel named yet
    QVERIFY(local->writeFrame(QCanBusFrame(0x101, QByteArray::fromHex("01"))));
    QTcpSocket other; // and a frame from another client on the same channel, and one on can0
    other.connectToHost(QHostAddress::LocalHost, hub.port());
    QVERIFY(other.waitForConnected(5000));
    other.write("connect:can1\ncan1:258##02\ncan0:259##03\n");
    QVERIFY(other.waitForBytesWritten(5000));
    QCOMPARE(receive(local.get(), 1).size(), 1); // the hub has read the frames
    late.write("connect:can1\n");
    QVERIFY(late.waitForBytesWritten(5000));
    QByteArray got;
    QElapsedTimer t;
    t.start();
    while (got.count('\n') < 2 && t.elapsed() < 3000) {
        QTest::qWait(5);
        got += late.readAll();
    }
    QCOMPARE(got, QByteArray("257##01\n258##02\n"));
}

void TestVirtualCanHub::badLinesReachNobody()
{
    VirtualCanHub hub;
    QVERIFY(hub.start());
    auto local = localDevice(hub, 0);
    QVERIFY(local);
    QTcpSocket raw;
    raw.connectToHost(QHostAddress::LocalHost, hub.port());
    QVERIFY(raw.waitForConnected(5000));
    raw.write("connect:can0\ncan0:notanid##11\ncan0:12#11\nno colon\n:\ncan0:291##33\n");
    QVERIFY(raw.waitForBytesWritten(5000));
    const QList<QCanBusFrame> frames = receive(local.get(), 2, 300);
    QCOMPARE(frames.size(), 1); // only the good line
    QCOMPARE(frames.at(0).frameId(), 291u);
    QCOMPARE(frames.at(0).payload().toHex(), QByteArray("33"));
}

void TestVirtualCanHub::localDeviceNeedsARunningHub()
{
    VirtualCanHub hub; // not started
    std::unique_ptr<QCanBusDevice> d(hub.createLocalDevice(0));
    QVERIFY(!d->connectDevice());
    QCOMPARE(d->error(), QCanBusDevice::ConnectionError);
    QVERIFY(!d->errorString().isEmpty());
    QVERIFY(!d->writeFrame(QCanBusFrame(0x1, QByteArray())));
}

QTEST_GUILESS_MAIN(TestVirtualCanHub)
#include "tst_virtualcanhub.moc"
