// Interop: Qt's own `canbusutil` (package libqt6serialbus6-bin) talks to SimServoCanDrive on
// virtualcan. canbusutil is software nobody on this project wrote: if it sees our heartbeats
// and gets the 0x12 replies the protocol document describes, the simulator speaks servo-can
// on the wire and not just to our own host code.
//
// canbusutil is the independent listener: it prints what is on the wire (heartbeats,
// requests, replies). Requests are sent by a plain QCanBusDevice in this test, because
// canbusutil 6.4 cannot send on virtualcan: it writes its frame right after connectDevice(),
// before the plugin's asynchronous TCP connect completes ("Cannot write frame as client is
// not connected!"), and exits.
//
// The bus is a VirtualCanHub on a free port (tcp://127.0.0.1:PORT/can0), so this test never
// meets another process's virtualcan bus on the fixed port 35468.
#include <QtTest>

#include "sim/bus/simcanbus.h"
#include "sim/bus/virtualcanhub.h"
#include "sim/servocan/simservocandrive.h"
#include "tests/support/requiretool.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QCanBusFrame>
#include <QLibraryInfo>
#include <QProcess>
#include <QRegularExpression>

#include <memory>

using namespace dd;

namespace {

constexpr int kStation = 3; // ID 0x067

// Every frame below is written by hand from the seed (ID 0x64 + station; b0 station, b1
// command, b2..b6 payload, b7 0xFF; int32 little-endian in b3..b6), never by the project's
// servo-can encoder, so a misreading shared by codec and simulator cannot pass.
//
// "067" and "03 10 88 00 00 00 00 FF" as canbusutil prints a frame: the ID in hex, then the
// bytes in upper-case hex separated by spaces (the exact column layout is not relied on).
QRegularExpression onWire(const char *id, const char *bytes)
{
    const QString b = QString::fromLatin1(bytes).split(QLatin1Char(' ')).join(QStringLiteral("\\s+"));
    return QRegularExpression(QStringLiteral("\\b0*%1\\b.*\\b%2\\b").arg(QLatin1String(id), b),
                              QRegularExpression::CaseInsensitiveOption);
}

// An idle heartbeat (cmd 0x10, state 0x88) of station 3 at `position`, bytes spelled out.
QRegularExpression idleHeartbeatAt(qint32 position)
{
    const auto u = quint32(position);
    const QByteArray pos = QStringLiteral("%1 %2 %3 %4")
                               .arg(u & 0xFF, 2, 16, QLatin1Char('0'))
                               .arg((u >> 8) & 0xFF, 2, 16, QLatin1Char('0'))
                               .arg((u >> 16) & 0xFF, 2, 16, QLatin1Char('0'))
                               .arg(u >> 24, 2, 16, QLatin1Char('0'))
                               .toUpper()
                               .toLatin1();
    return onWire("67", QByteArray("03 10 88 " + pos + " FF").constData());
}

} // namespace

class TestServoCanCanbusutil : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void listenerPrintsHeartbeats();
    void readRequestIsAnswered();
    void writeThenReadBack();
    void jogStopsByWatchdogWithoutKeepAlive();

private:
    QProcess *startListener();
    bool waitForOutput(QProcess *p, const QRegularExpression &re, int ms);
    bool send(const char *bytes); // to station 3, ID 0x067

    QString m_tool;
    std::unique_ptr<VirtualCanHub> m_hub;
    std::unique_ptr<SimCanBus> m_bus;
    std::unique_ptr<QCanBusDevice> m_sender;
    SimServoCanDrive *m_sim = nullptr;
    QList<QProcess *> m_processes;
    QHash<QProcess *, QString> m_output;
};

void TestServoCanCanbusutil::initTestCase()
{
    m_tool = QLibraryInfo::path(QLibraryInfo::BinariesPath) + QStringLiteral("/canbusutil");
    if (!QFileInfo::exists(m_tool))
        m_tool = QStandardPaths::findExecutable(QStringLiteral("canbusutil"));
    DD_REQUIRE_TOOL(!m_tool.isEmpty() && QFileInfo::exists(m_tool),
                    "canbusutil not installed (Debian: libqt6serialbus6-bin)");
    m_hub = std::make_unique<VirtualCanHub>();
    QVERIFY(m_hub->start());
    m_bus = std::make_unique<SimCanBus>();
    m_sim = static_cast<SimServoCanDrive *>(m_bus->addDevice(std::make_unique<SimServoCanDrive>(kStation)));
    const Error e = m_bus->open(QStringLiteral("virtualcan"), m_hub->interfaceName(0));
    QVERIFY2(!e.isError(), qPrintable(e.message));
    QTRY_VERIFY_WITH_TIMEOUT(m_bus->isConnected(), 5000);
    m_sender.reset(QCanBus::instance()->createDevice(QStringLiteral("virtualcan"), m_hub->interfaceName(0)));
    QVERIFY(m_sender);
    QVERIFY(m_sender->connectDevice());
    QTRY_COMPARE_WITH_TIMEOUT(m_sender->state(), QCanBusDevice::ConnectedState, 5000);
}

void TestServoCanCanbusutil::cleanupTestCase()
{
    for (QProcess *p : std::as_const(m_processes)) {
        if (p->state() != QProcess::NotRunning) {
            p->kill();
            p->waitForFinished(2000);
        }
        delete p;
    }
    m_sender.reset();
    m_bus.reset();
    m_hub.reset();
}

QProcess *TestServoCanCanbusutil::startListener()
{
    auto *p = new QProcess;
    m_processes.append(p);
    p->setProcessChannelMode(QProcess::MergedChannels);
    connect(p, &QProcess::readyRead, this, [this, p] { m_output[p] += QString::fromLocal8Bit(p->readAll()); });
    p->start(m_tool, {QStringLiteral("-l"), QStringLiteral("virtualcan"), m_hub->interfaceName(0)});
    return p;
}

bool TestServoCanCanbusutil::waitForOutput(QProcess *p, const QRegularExpression &re, int ms)
{
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < ms) {
        if (re.match(m_output.value(p)).hasMatch())
            return true;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    }
    qWarning().noquote() << "canbusutil printed:\n" << m_output.value(p).right(2000);
    return false;
}

bool TestServoCanCanbusutil::send(const char *bytes)
{
    return m_sender->writeFrame(QCanBusFrame(0x64 + kStation, QByteArray::fromHex(bytes)));
}

void TestServoCanCanbusutil::listenerPrintsHeartbeats()
{
    QProcess *l = startListener();
    QVERIFY(l->waitForStarted(5000));
    // Idle heartbeat of station 3 at position 0: 067 03 10 88 00 00 00 00 FF.
    QVERIFY(waitForOutput(l, onWire("67", "03 10 88 00 00 00 00 FF"), 5000));
}

void TestServoCanCanbusutil::readRequestIsAnswered()
{
    QProcess *l = startListener();
    QVERIFY(waitForOutput(l, onWire("67", "03 10 88 00 00 00 00 FF"), 5000)); // connected
    // 0x12 / 0xFA read of P75 (station number): the reply carries 3 in b5..b6.
    QVERIFY(send("03 12 FA 4B 00 00 00 FF"));
    QVERIFY(waitForOutput(l, onWire("67", "03 12 FA 4B 00 00 00 FF"), 5000)); // the request
    QVERIFY(waitForOutput(l, onWire("67", "03 12 FA 4B 00 03 00 FF"), 5000)); // P75 = 3
    // Bus voltage (0xAB): int32 in b3..b6, about 310 V.
    QVERIFY(send("03 12 AB 00 00 00 00 FF"));
    QVERIFY(waitForOutput(
        l,
        QRegularExpression(QStringLiteral("\\b0*67\\b.*\\b03\\s+12\\s+AB\\s+3[0-9A-F]\\s+01\\s+00\\s+00\\s+FF"),
                           QRegularExpression::CaseInsensitiveOption),
        5000));
}

void TestServoCanCanbusutil::writeThenReadBack()
{
    QProcess *l = startListener();
    QVERIFY(waitForOutput(l, onWire("67", "03 10 88 00 00 00 00 FF"), 5000));
    // 0x15, b2 = 0x01 write parameter, b3 = index 42 (0x2A), b4 = 0, b5..b6 = -2 (FE FF).
    QVERIFY(send("03 15 01 2A 00 FE FF FF"));
    QTRY_COMPARE_WITH_TIMEOUT(m_sim->parameter(42), qint16(-2), 3000);
    QVERIFY(send("03 12 FA 2A 00 00 00 FF"));
    QVERIFY(waitForOutput(l, onWire("67", "03 12 FA 2A 00 FE FF FF"), 5000));
}

void TestServoCanCanbusutil::jogStopsByWatchdogWithoutKeepAlive()
{
    // One jog frame (+100 r/min, the seed's example: 067#03 20 00 64 00 00 00 FF) and no
    // keep-alive: the drive runs, then its 2 s watchdog stops it and keeps it enabled. The
    // heartbeats canbusutil prints show it running (state 00), then idle (88) again.
    QProcess *l = startListener();
    QVERIFY(waitForOutput(l, onWire("67", "03 10 88 00 00 00 00 FF"), 5000));
    const quint64 trips = m_sim->stats().watchdogTrips;
    QVERIFY(send("03 20 00 64 00 00 00 FF"));
    QTRY_VERIFY_WITH_TIMEOUT(qAbs(m_sim->motor().speedRpm() - 100) < 1, 2000);
    QElapsedTimer t;
    t.start();
    QTRY_VERIFY_WITH_TIMEOUT(!m_sim->motor().isMoving(), 4000);
    QVERIFY2(t.elapsed() > 1000, "stopped long before the 2 s watchdog");
    QCOMPARE(m_sim->stats().watchdogTrips, trips + 1);
    QVERIFY(m_sim->motor().isEnabled());
    QVERIFY(waitForOutput(l,
                          QRegularExpression(QStringLiteral("\\b0*67\\b.*\\b03\\s+10\\s+00\\s"),
                                             QRegularExpression::CaseInsensitiveOption),
                          1000));
    const qint32 pos = static_cast<qint32>(m_sim->motor().position());
    QVERIFY(pos > 0);
    QVERIFY(waitForOutput(l, idleHeartbeatAt(pos), 2000));
}

QTEST_GUILESS_MAIN(TestServoCanCanbusutil)
#include "tst_servocan_canbusutil.moc"
