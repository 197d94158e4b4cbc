// The simulator and a CanLink on another thread on one VirtualCanHub, as bench_speed and the
// GUI's demo bench run them: Qt 6.4's virtualcan plugin keeps one process-wide server object
// and asked it to start on every connect to a loopback address, creating a child across
// threads ("QObject: Cannot create children for a parent that is in a different thread
// (Parent is VirtualCanServer ...)") when the client's thread was not the simulator's.
// VirtualCanHub::start() settles that server first (see virtualcanhub.h).
//
// One test function: the plugin's server object is per process, so the first virtualcan
// device of this binary must be opened here.

#include "core/link/canlink.h"
#include "core/link/cansettings.h"
#include "sim/bus/simcanbus.h"
#include "sim/bus/virtualcanhub.h"

#include <QMutex>
#include <QSignalSpy>
#include <QTest>
#include <QThread>

using namespace dd;

namespace {
QMutex g_mutex;
QStringList g_messages;
QtMessageHandler g_previous = nullptr;

void collect(QtMsgType type, const QMessageLogContext &context, const QString &message)
{
    {
        QMutexLocker lock(&g_mutex);
        g_messages.append(message);
    }
    if (g_previous)
        g_previous(type, context, message);
}

QStringList crossThreadWarnings()
{
    QMutexLocker lock(&g_mutex);
    QStringList out;
    for (const QString &m : std::as_const(g_messages))
        if (m.contains(QLatin1String("different thread")))
            out.append(m);
    return out;
}
} // namespace

class TestVirtualCanThreads : public QObject
{
    Q_OBJECT
private slots:
    void simulatorAndLinkOnTwoThreads();
};

void TestVirtualCanThreads::simulatorAndLinkOnTwoThreads()
{
    g_previous = qInstallMessageHandler(collect);

    VirtualCanHub hub;
    QVERIFY(hub.start());
    // The simulator's side on this thread: the plugin's server object is created here.
    SimCanBus bus;
    const Error e = bus.open(QStringLiteral("virtualcan"), hub.interfaceName(0));
    QVERIFY2(!e.isError(), qPrintable(e.message));
    QTRY_VERIFY_WITH_TIMEOUT(bus.isConnected(), 5000);
    QSignalSpy received(&bus, &SimCanBus::frameReceived);

    // The client's side on a thread of its own, as DriveHub's I/O thread.
    QThread io;
    io.start();
    auto *link = new CanLink;
    link->moveToThread(&io);
    QSignalSpy linkConnected(link, &CanLink::connected);
    CanSettings settings;
    QVERIFY(CanSettings::parse(QStringLiteral("virtualcan:") + hub.interfaceName(0), &settings));
    bool opened = false;
    QMetaObject::invokeMethod(
        link, [&] { opened = link->open(settings); }, Qt::BlockingQueuedConnection);
    QVERIFY(opened);
    QTRY_COMPARE_WITH_TIMEOUT(linkConnected.count(), 1, 5000);

    // The bus works across the threads: a frame from the link reaches the simulator.
    QMetaObject::invokeMethod(
        link,
        [link] {
            link->send({0x601, QByteArray::fromHex("0102030405060708"), false});
        },
        Qt::BlockingQueuedConnection);
    QTRY_COMPARE_WITH_TIMEOUT(received.count(), 1, 5000);
    QCOMPARE(received.at(0).at(0).value<CanFrameData>().id, 0x601u);

    QMetaObject::invokeMethod(
        link, [link] { delete link; }, Qt::BlockingQueuedConnection);
    io.quit();
    io.wait();
    qInstallMessageHandler(g_previous);

    const QStringList warnings = crossThreadWarnings();
    QVERIFY2(warnings.isEmpty(), qPrintable(warnings.join(QLatin1Char('\n'))));
}

QTEST_GUILESS_MAIN(TestVirtualCanThreads)
#include "tst_virtualcanthreads.moc"
