// The whole servo-can host stack (ServoCanBackend: CanLink, station tracker, drives,
// discovery) against SimCanBus + SimServoCanDrive on Qt's virtualcan plugin.
//
// Isolation: virtualcan's first device hosts a TCP server; with the plain interface names
// (can0/can1) that is the fixed port 35468, shared with every other test process on the
// machine. Here a VirtualCanHub (the plugin's line protocol, TCP_NODELAY) listens on a free
// port and every device names it ("tcp://127.0.0.1:PORT/can1"), so parallel ctest runs
// never share a bus and pipelined reads do not stall on Nagle's algorithm.
#include <QtTest>

#include "core/drive/servocan/servocanbackend.h"
#include "core/drive/servocan/servocandrive.h"
#include "core/drive/servocan/servocanstationtracker.h"
#include "core/link/canlink.h"
#include "core/link/connectionsettings.h"
#include "core/link/traffictap.h"
#include "core/protocol/servocan/servocan.h"
#include "sim/bus/simcanbus.h"
#include "sim/bus/virtualcanhub.h"
#include "sim/servocan/simservocandrive.h"

#include <QElapsedTimer>

#include <cmath>
#include <memory>

using namespace dd;
namespace sc = dd::servocan;

namespace {

bool waitFinished(DriveReply *r, int ms = 5000)
{
    QElapsedTimer t;
    t.start();
    while (!r->isFinished() && t.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    QCoreApplication::processEvents(); // deliver the queued finished()
    return r->isFinished();
}

QString errorText(const DriveReply *r)
{
    return errorCodeName(r->error().code) + QStringLiteral(": ") + r->error().message;
}

} // namespace

class TestServoCanDrive : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();

    void discoveryFindsStations();
    void keepAliveKeepsDrivesConnected();
    void motionLeaseEndsWhenTheMoveEnds();
    void readAllParameters();
    void writeReadsBackAndVerifies();
    void outOfRangeWriteSendsNothing();
    void refusedWriteIsAMismatch();
    void identityChecksCanMode();
    void channelsReadLiveValues();
    void jogRunsAndStopStops();
    void jogLeaseStopsTheAxis();
    void movesEndOnTarget();
    void setPositionReadsBack();
    void alarmSeenAndCleared();
    void motionRefusedWhileAlarmed();
    void emergencyStopDisables();
    void dropFaultsAreRetried();
    void corruptFaultsNeedConfirmedReads();
    void silentStationGoesOffline();
    void watchdogStopsMotionWithoutKeepAlive(); // closes and reopens the link
    void busGoingAwayIsALostLink();             // ends the bus: keep it last

private:
    bool openBackend();
    ServoCanDrive *drive(int station) { return m_backend->servoDrive(station); }
    bool waitUntil(const std::function<bool()> &cond, int ms);
    QList<CanFrameData> sentFrames(sc::Command command) const;

    QString m_can;
    std::unique_ptr<VirtualCanHub> m_hub;
    std::unique_ptr<SimCanBus> m_bus;
    SimServoCanDrive *m_sim1 = nullptr;
    SimServoCanDrive *m_sim7 = nullptr;
    std::unique_ptr<TrafficTap> m_tap;
    std::unique_ptr<ServoCanBackend> m_backend;
    QList<TrafficRecord> m_tx;
};

bool TestServoCanDrive::waitUntil(const std::function<bool()> &cond, int ms)
{
    QElapsedTimer t;
    t.start();
    while (!cond() && t.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    return cond();
}

QList<CanFrameData> TestServoCanDrive::sentFrames(sc::Command command) const
{
    QList<CanFrameData> out;
    for (const TrafficRecord &r : m_tx)
        if (r.bytes.size() == 8 && quint8(r.bytes.at(1)) == quint8(command))
            out.append({r.canId, r.bytes, r.canExtended});
    return out;
}

void TestServoCanDrive::initTestCase()
{
    m_hub = std::make_unique<VirtualCanHub>();
    QVERIFY(m_hub->start());
    m_can = QStringLiteral("virtualcan:") + m_hub->interfaceName(1);
    m_bus = std::make_unique<SimCanBus>();
    m_sim1 = static_cast<SimServoCanDrive *>(m_bus->addDevice(std::make_unique<SimServoCanDrive>(1)));
    m_sim7 = static_cast<SimServoCanDrive *>(m_bus->addDevice(std::make_unique<SimServoCanDrive>(7)));
    const Error e = m_bus->open(QStringLiteral("virtualcan"), m_hub->interfaceName(1));
    QVERIFY2(!e.isError(), qPrintable(e.message));
    QTRY_VERIFY_WITH_TIMEOUT(m_bus->isConnected(), 5000);
    QCOMPARE(VirtualCanHub::setLowDelay(m_bus->canDevice()), 1); // until SimCanBus does it
    if (qEnvironmentVariableIsSet("TRACE_CAN")) {
        connect(m_bus.get(), &SimCanBus::frameReceived, this, [](const CanFrameData &f, qint64 at) {
            qInfo() << "SIM IN " << at << Qt::hex << f.id << f.data.toHex(' ');
        });
        connect(m_bus.get(), &SimCanBus::frameSent, this, [](const CanFrameData &f, qint64 at, int) {
            qInfo() << "SIM OUT" << at << Qt::hex << f.id << f.data.toHex(' ');
        });
    }

    m_tap = std::make_unique<TrafficTap>();
    connect(m_tap.get(), &TrafficTap::frameRecorded, this, [this](const TrafficRecord &r) {
        if (r.direction == TrafficRecord::Direction::Tx)
            m_tx.append(r);
        if (qEnvironmentVariableIsSet("TRACE_CAN"))
            qInfo() << r.timestampUs << r.directionText() << r.hexText() << r.note;
    });
    m_backend = std::make_unique<ServoCanBackend>();
    QVERIFY(openBackend());
}

bool TestServoCanDrive::openBackend()
{
    ConnectionSettings cs;
    cs.family = Family::ServoCan;
    cs.can = m_can;
    cs.retries = 6; // the fault tests drop replies
    Error e;
    if (!m_backend->open(cs, m_tap.get(), &e)) {
        qWarning() << e.message;
        return false;
    }
    // Both stations heard (heartbeats every 30 ms).
    return waitUntil([this] { return m_backend->tracker()->onlineStations() == QList<int>({1, 7}); }, 3000);
}

void TestServoCanDrive::cleanupTestCase()
{
    m_backend.reset();
    m_bus.reset();
    m_hub.reset();
}

void TestServoCanDrive::init()
{
    m_tx.clear();
    for (SimServoCanDrive *s : {m_sim1, m_sim7}) {
        s->faults().setSettings(FaultSettings());
        if (s->alarmCode() != 0)
            s->motor().clearAlarm();
        s->motor().stop();
    }
    QVERIFY(waitUntil([this] { return !m_sim1->motor().isMoving() && !m_sim7->motor().isMoving(); }, 3000));
    for (int st : {1, 7}) {
        drive(st)->setConfirmReads(false);
        drive(st)->setEmergencyStopHolds(false);
    }
}

void TestServoCanDrive::discoveryFindsStations()
{
    ScanOptions o;
    o.listenMs = 300;
    Discovery *d = m_backend->createDiscovery(o);
    QSignalSpy finished(d, &Discovery::finished);
    QElapsedTimer t;
    t.start();
    d->start();
    QVERIFY(finished.wait(3000));
    QVERIFY2(t.elapsed() >= 280, "discovery must listen for listenMs");
    QCOMPARE(finished.first().first().value<Error>().code, ErrorCode::None);
    QList<int> found;
    for (const DiscoveredDrive &dd : d->results()) {
        found.append(dd.address);
        QCOMPARE(dd.family, Family::ServoCan);
        QCOMPARE(dd.bitrate, 1000000);
        QCOMPARE(dd.state, QStringLiteral("idle"));
    }
    std::sort(found.begin(), found.end());
    QCOMPARE(found, QList<int>({1, 7}));
    delete d;
}

void TestServoCanDrive::keepAliveKeepsDrivesConnected()
{
    ServoCanStationTracker *tr = m_backend->tracker();
    tr->resetStats();
    const quint64 kaBefore = m_sim7->stats().keepAlives;
    const quint64 ka1Before = m_sim1->stats().keepAlives;
    const quint64 tripsBefore = m_sim7->stats().watchdogTrips;
    // Run the axis for longer than the drive's 2 s watchdog while the lease is renewed.
    ServoCanDrive *d = drive(7);
    DriveReply *r = d->jog(200);
    QVERIFY(waitFinished(r));
    QVERIFY2(r->ok(), qPrintable(errorText(r)));
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < 2600) {
        d->renewJogLease();
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    }
    QVERIFY(m_sim7->motor().isMoving());
    QVERIFY(m_sim7->isHostOnline());
    QCOMPARE(m_sim7->stats().watchdogTrips, tripsBefore);
    const quint64 received = m_sim7->stats().keepAlives - kaBefore;
    QVERIFY2(received >= 22, qPrintable(QStringLiteral("%1 keep-alives in 2.6 s").arg(received)));
    qInfo("keep-alive: %llu ticks, max gap %.1f ms", static_cast<unsigned long long>(tr->stats().keepAliveTicks),
          tr->stats().maxKeepAliveGapMs);
    QVERIFY2(tr->stats().maxKeepAliveGapMs < 500, "keep-alive gap far beyond 100 ms");
    QVERIFY(tr->holdsMotion(7));
    QVERIFY(waitFinished(d->stop()));
    QVERIFY(!tr->holdsMotion(7)); // the stop ends the motion lease, and with it the keep-alive
    QVERIFY(waitUntil([this] { return !m_sim7->motor().isMoving(); }, 2000));
    // The keep-alive goes only to the station whose motion this program commands: station 1,
    // heard but at rest, got none (issue 26: a reader must not keep another's motion alive).
    QCOMPARE(m_sim1->stats().keepAlives, ka1Before);
    const quint64 frames = tr->stats().keepAliveFrames;
    QTest::qWait(300);
    QCOMPARE(tr->stats().keepAliveFrames, frames);
}

void TestServoCanDrive::motionLeaseEndsWhenTheMoveEnds()
{
    // A move holds its station's motion lease (keep-alive) while it runs and gives it up
    // when the heartbeat shows the axis at rest at its end: nobody sends a stop.
    ServoCanStationTracker *tr = m_backend->tracker();
    ServoCanDrive *d = drive(7);
    QVERIFY(!tr->holdsMotion(7));
    const quint64 ka = m_sim7->stats().keepAlives;
    DriveReply *r = d->moveRelative(20000, 600);
    QVERIFY(waitFinished(r));
    QVERIFY2(r->ok(), qPrintable(errorText(r)));
    QVERIFY(tr->holdsMotion(7));
    QVERIFY(m_sim7->stats().keepAlives > ka);
    QVERIFY(waitUntil([this] { return !m_sim7->motor().isMoving(); }, 5000));
    QVERIFY(waitUntil([tr] { return !tr->holdsMotion(7); }, 1000));
    const quint64 after = m_sim7->stats().keepAlives;
    QTest::qWait(300);
    QCOMPARE(m_sim7->stats().keepAlives, after);
}

void TestServoCanDrive::readAllParameters()
{
    m_sim1->setParameter(100, -32768);
    m_sim1->setParameter(101, 32767);
    const quint64 retriesBefore = m_backend->link()->retryCount();
    DriveReply *r = drive(1)->readParameters(ServoCanDrive::allParameterIndices());
    QSignalSpy progress(r, &DriveReply::progress);
    QElapsedTimer t;
    t.start();
    QVERIFY(waitFinished(r));
    QVERIFY2(r->ok(), qPrintable(errorText(r)));
    qInfo("220 parameters in %lld ms", static_cast<long long>(t.elapsed()));
    QCOMPARE(r->parameters().size(), 220);
    for (int i = 0; i < 220; ++i)
        QCOMPARE(r->parameters().value(i), qint64(m_sim1->parameter(i)));
    QCOMPARE(r->parameters().value(75), 1);
    QCOMPARE(r->parameters().value(100), -32768);
    QVERIFY(progress.size() > 0);
    QCOMPARE(progress.last().at(0).toInt(), 220);
    // All 220 reads went out (pipelined), none twice.
    // All 220 reads went out pipelined; only a timeout (a loaded machine) repeats one.
    const quint64 retries = m_backend->link()->retryCount() - retriesBefore;
    if (retries > 0)
        qInfo("%llu reads repeated after a timeout", static_cast<unsigned long long>(retries));
    QCOMPARE(quint64(sentFrames(sc::Command::Read).size()), 220 + retries);
}

void TestServoCanDrive::writeReadsBackAndVerifies()
{
    DriveReply *r = drive(7)->writeParameters({{10, 1234}, {200, -5}, {11, 0}});
    QVERIFY(waitFinished(r));
    QVERIFY2(r->ok(), qPrintable(errorText(r)));
    QCOMPARE(r->writeResults().size(), 3);
    for (const ParameterWriteResult &w : r->writeResults()) {
        QVERIFY(w.written);
        QVERIFY(w.verified);
        QCOMPARE(w.readBack, w.requested);
    }
    QCOMPARE(m_sim7->parameter(10), qint16(1234));
    QCOMPARE(m_sim7->parameter(200), qint16(-5));
    QCOMPARE(m_sim1->parameter(10), SimServoCanDrive::defaultParameters(1)[10]); // other station untouched
    // Each write is followed by its read-back on the wire.
    const QList<CanFrameData> writes = sentFrames(sc::Command::Write);
    QCOMPARE(writes.size(), 3);
    QCOMPARE(writes.first(), sc::writeParameter(7, 10, 1234));
}

void TestServoCanDrive::outOfRangeWriteSendsNothing()
{
    const qint16 before = m_sim7->parameter(12);
    DriveReply *r = drive(7)->writeParameters({{12, 100}, {13, 40000}});
    QVERIFY(waitFinished(r));
    QCOMPARE(r->error().code, ErrorCode::OutOfRange);
    DriveReply *r2 = drive(7)->writeParameters({{220, 1}});
    QVERIFY(waitFinished(r2));
    QCOMPARE(r2->error().code, ErrorCode::InvalidArgument);
    QTest::qWait(50);
    QVERIFY(sentFrames(sc::Command::Write).isEmpty());
    QVERIFY(sentFrames(sc::Command::Read).isEmpty());
    QCOMPARE(m_sim7->parameter(12), before); // the valid one was not sent either
}

void TestServoCanDrive::refusedWriteIsAMismatch()
{
    // The dictionary knows P75 is 0..99: refused before sending.
    DriveReply *r = drive(7)->writeParameters({{75, 150}});
    QVERIFY(waitFinished(r));
    QCOMPARE(r->error().code, ErrorCode::OutOfRange);
    QVERIFY(sentFrames(sc::Command::Write).isEmpty());
    // A drive that ignores the write: caught by the read-back, after 1 + retries attempts.
    m_sim7->setWriteProtected(30, true);
    const qint16 before = m_sim7->parameter(30);
    r = drive(7)->writeParameters({{31, 5}, {30, 99}});
    QVERIFY(waitFinished(r));
    m_sim7->setWriteProtected(30, false);
    QCOMPARE(r->error().code, ErrorCode::VerifyMismatch);
    QCOMPARE(r->writeResults().size(), 2);
    QVERIFY(r->writeResults().at(0).verified);
    const ParameterWriteResult &w = r->writeResults().at(1);
    QCOMPARE(w.index, 30);
    QVERIFY(w.written);
    QVERIFY(!w.verified);
    QCOMPARE(w.readBack, qint64(before));
    QVERIFY(!w.error.isEmpty());
    QCOMPARE(w.outcome, WriteOutcome::Mismatch);
    QCOMPARE(w.error, QStringLiteral("Wrote 99, but the drive reads back %1. Written 7 time(s).").arg(before));
    QVERIFY2(r->error().message.contains(QStringLiteral("(first: P30: Wrote 99")), qPrintable(r->error().message));
    QCOMPARE(sentFrames(sc::Command::Write).size(), 1 + 7); // P31 once, P30 1 + retries (6)
}

void TestServoCanDrive::identityChecksCanMode()
{
    DriveReply *r = drive(1)->refreshIdentity();
    QVERIFY(waitFinished(r));
    QVERIFY2(r->ok(), qPrintable(errorText(r)));
    QCOMPARE(r->info().value(QStringLiteral("station")).toInt(), 1);
    QVERIFY(r->info().value(QStringLiteral("warnings")).toStringList().isEmpty());
    m_sim1->setParameter(4, 0);
    r = drive(1)->refreshIdentity();
    QVERIFY(waitFinished(r));
    QCOMPARE(r->info().value(QStringLiteral("warnings")).toStringList().size(), 1);
    m_sim1->setParameter(4, 8);
    QCOMPARE(drive(1)->identity().family, Family::ServoCan);
    QCOMPARE(drive(1)->identity().address, 1);
}

void TestServoCanDrive::channelsReadLiveValues()
{
    ServoCanDrive *d = drive(1);
    QStringList ids;
    for (const ChannelInfo &c : d->channels())
        ids << c.id;
    QCOMPARE(ids.size(), 14);
    DriveReply *r = d->readChannels(ids);
    QVERIFY(waitFinished(r));
    QVERIFY2(r->ok(), qPrintable(errorText(r)));
    QCOMPARE(r->samples().size(), 14);
    QVERIFY(qAbs(r->samples().value(QStringLiteral("bus-voltage")) - 310) < 20);
    QVERIFY(qAbs(r->samples().value(QStringLiteral("temperature")) - 25) < 10);
    QCOMPARE(r->samples().value(QStringLiteral("alarm")), 0.0);
    QCOMPARE(r->samples().value(QStringLiteral("position")), double(m_sim1->motor().position()));
    DriveReply *bad = d->readChannels({QStringLiteral("speed"), QStringLiteral("no-such")});
    QVERIFY(waitFinished(bad));
    QCOMPARE(bad->error().code, ErrorCode::InvalidArgument);
}

void TestServoCanDrive::jogRunsAndStopStops()
{
    ServoCanDrive *d = drive(1);
    d->setJogLeaseMs(5000);
    DriveReply *r = d->jog(300);
    QVERIFY(waitFinished(r));
    QVERIFY2(r->ok(), qPrintable(errorText(r)));
    QVERIFY(d->status().running);
    QVERIFY(d->status().enabled);
    QVERIFY(waitUntil([this] { return qAbs(m_sim1->motor().speedRpm() - 300) < 1; }, 2000));
    DriveReply *sp = d->readChannels({QStringLiteral("speed")});
    QVERIFY(waitFinished(sp));
    // The simulator's closed loop holds the command: within 5 r/min (its load and friction
    // ripple the speed by a few r/min, as a real loop's would).
    QVERIFY2(qAbs(sp->samples().value(QStringLiteral("speed")) - 300.0) <= 5.0,
             qPrintable(QString::number(sp->samples().value(QStringLiteral("speed")))));
    const qint64 p0 = d->status().position;
    QVERIFY(waitUntil([d, p0] { return d->status().position > p0 + 1000; }, 2000)); // heartbeats follow
    r = d->stop();
    QVERIFY(waitFinished(r));
    QVERIFY(r->ok());
    QVERIFY(!d->isJogging());
    QVERIFY(waitUntil([this] { return !m_sim1->motor().isMoving(); }, 2000));
    QVERIFY(waitUntil([d] { return !d->status().running; }, 1000));
    QVERIFY(m_sim1->motor().isEnabled());              // 0x26 holds the shaft
    QCOMPARE(sentFrames(sc::Command::Stop).size(), 2); // at once and behind the queue
    d->setJogLeaseMs(300);
}

void TestServoCanDrive::jogLeaseStopsTheAxis()
{
    ServoCanDrive *d = drive(7);
    QSignalSpy expired(d, &Drive::jogLeaseExpired);
    DriveReply *r = d->jog(-150);
    QVERIFY(waitFinished(r));
    QVERIFY(r->ok());
    QVERIFY(expired.wait(2000)); // nobody renews the 300 ms lease
    QVERIFY(waitUntil([this] { return !m_sim7->motor().isMoving(); }, 2000));
}

void TestServoCanDrive::movesEndOnTarget()
{
    ServoCanDrive *d = drive(7);
    // From the commanded position: after the previous test's stop the shaft may still settle
    // a few counts away from it (closed loop).
    const qint64 start = std::llround(m_sim7->motor().referencePosition());
    DriveReply *r = d->moveRelative(25000, 600);
    QVERIFY(waitFinished(r));
    QVERIFY2(r->ok(), qPrintable(errorText(r)));
    QCOMPARE(m_sim7->positioningSpeed(), 600);
    QVERIFY(waitUntil([d, start] { return !d->status().running && d->status().position == start + 25000; }, 5000));
    QCOMPARE(m_sim7->motor().position(), start + 25000);
    QCOMPARE(d->status().position, start + 25000);

    r = d->moveAbsolute(-4321, 900);
    QVERIFY(waitFinished(r));
    QVERIFY2(r->ok(), qPrintable(errorText(r)));
    QVERIFY(waitUntil([d] { return !d->status().running && d->status().position == -4321; }, 5000));
    QCOMPARE(m_sim7->motor().position(), -4321);
    // The positioning speed goes out before each move.
    const QList<CanFrameData> speeds = sentFrames(sc::Command::PositioningSpeed);
    QCOMPARE(speeds.size(), 2);
    QCOMPARE(speeds.last(), sc::positioningSpeed(7, 900));

    DriveReply *bad = d->moveRelative(1000, 0);
    QVERIFY(waitFinished(bad));
    QCOMPARE(bad->error().code, ErrorCode::InvalidArgument);
    bad = d->moveAbsolute(qint64(1) << 40, 100);
    QVERIFY(waitFinished(bad));
    QCOMPARE(bad->error().code, ErrorCode::OutOfRange);
}

void TestServoCanDrive::setPositionReadsBack()
{
    DriveReply *r = drive(1)->setPosition(123456);
    QVERIFY(waitFinished(r));
    QVERIFY2(r->ok(), qPrintable(errorText(r)));
    QCOMPARE(m_sim1->motor().position(), 123456);
    QCOMPARE(drive(1)->status().position, 123456);
}

void TestServoCanDrive::alarmSeenAndCleared()
{
    ServoCanDrive *d = drive(7);
    QSignalSpy alarms(d, &Drive::alarmChanged);
    m_sim7->injectAlarm(12);
    QVERIFY(alarms.wait(1000)); // the 0x05 frame goes out at once
    QCOMPARE(alarms.last().first().toInt(), 12);
    QCOMPARE(d->status().alarmCode, 12);
    DriveReply *r = d->readAlarm();
    QVERIFY(waitFinished(r));
    QVERIFY(r->ok());
    QCOMPARE(r->status().alarmCode, 12);
    r = d->clearAlarm();
    QVERIFY(waitFinished(r));
    QVERIFY2(r->ok(), qPrintable(errorText(r)));
    QCOMPARE(d->status().alarmCode, 0);
    QCOMPARE(m_sim7->alarmCode(), 0);
    QCOMPARE(sentFrames(sc::Command::ClearAlarm).size(), 1);
}

void TestServoCanDrive::motionRefusedWhileAlarmed()
{
    ServoCanDrive *d = drive(1);
    m_sim1->injectAlarm(3);
    QVERIFY(waitUntil([d] { return d->status().alarmCode == 3; }, 1000));
    DriveReply *r = d->jog(100);
    QVERIFY(waitFinished(r));
    QCOMPARE(r->error().code, ErrorCode::DriveException); // no heartbeat showed it running
    QVERIFY(!m_sim1->motor().isMoving());
    QVERIFY(waitFinished(d->stop()));
}

void TestServoCanDrive::emergencyStopDisables()
{
    ServoCanDrive *d = drive(7);
    d->setJogLeaseMs(5000);
    DriveReply *r = d->jog(500);
    QVERIFY(waitFinished(r));
    QVERIFY(r->ok());
    m_backend->stopAll();
    QVERIFY(waitUntil([this] { return !m_sim7->motor().isMoving(); }, 2000));
    QVERIFY(waitUntil([this] { return !m_sim7->motor().isEnabled(); }, 1000)); // 0x28
    QVERIFY(!d->status().enabled);
    QVERIFY(!d->isJogging());
    // Both stations got it (station 1 was only heard, and has a drive from earlier tests).
    QSet<quint32> ids;
    for (const CanFrameData &f : sentFrames(sc::Command::StopAndDisable))
        ids.insert(f.id);
    QCOMPARE(ids, QSet<quint32>({sc::frameId(1), sc::frameId(7)}));
    d->setJogLeaseMs(300);
}

void TestServoCanDrive::dropFaultsAreRetried()
{
    m_sim1->faults().setSettings(*FaultSettings::parse(QStringLiteral("drop=0.1,seed=11")));
    DriveReply *r = drive(1)->readParameters(ServoCanDrive::allParameterIndices());
    QVERIFY(waitFinished(r, 15000));
    QVERIFY2(r->ok(), qPrintable(errorText(r)));
    for (int i = 0; i < 220; ++i)
        QCOMPARE(r->parameters().value(i), qint64(m_sim1->parameter(i)));
    QVERIFY(m_bus->stats().framesDropped > 0);
    QVERIFY(sentFrames(sc::Command::Read).size() > 220); // retried
    DriveReply *w = drive(1)->writeParameters({{20, 777}, {21, -777}});
    QVERIFY(waitFinished(w, 5000));
    QVERIFY2(w->ok(), qPrintable(errorText(w)));
    QCOMPARE(m_sim1->parameter(21), qint16(-777));
}

void TestServoCanDrive::corruptFaultsNeedConfirmedReads()
{
    m_sim1->faults().setSettings(*FaultSettings::parse(QStringLiteral("corrupt=0.05,seed=5")));
    drive(1)->setConfirmReads(true);
    DriveReply *r = drive(1)->readParameters(ServoCanDrive::allParameterIndices());
    QVERIFY(waitFinished(r, 15000));
    QVERIFY2(r->ok(), qPrintable(errorText(r)));
    QVERIFY(m_bus->stats().framesCorrupted > 0);
    for (int i = 0; i < 220; ++i)
        QCOMPARE(r->parameters().value(i), qint64(m_sim1->parameter(i)));
}

void TestServoCanDrive::silentStationGoesOffline()
{
    ServoCanDrive *d = drive(7);
    QVERIFY(d->status().online);
    QSignalSpy offline(m_backend->tracker(), &ServoCanStationTracker::stationOffline);
    m_sim7->faults().setSilent(true); // power loss
    QVERIFY(offline.wait(1000));
    QCOMPARE(offline.first().first().toInt(), 7);
    QVERIFY(!d->status().online);
    QVERIFY(m_backend->tracker()->isOnline(1));
    DriveReply *r = d->readAlarm();
    QVERIFY(waitFinished(r));
    QCOMPARE(r->error().code, ErrorCode::Timeout);
    r = d->jog(100);
    QVERIFY(waitFinished(r));
    QCOMPARE(r->error().code, ErrorCode::DriveException);
    QVERIFY(r->error().message.contains(QStringLiteral("heartbeat")));
    QVERIFY(waitFinished(d->stop()));
    // The stop ended the motion lease: no keep-alive keeps a drive this program cannot see.
    QVERIFY(!m_backend->tracker()->holdsMotion(7));
    const quint64 frames = m_backend->tracker()->stats().keepAliveFrames;
    QTest::qWait(250);
    QCOMPARE(m_backend->tracker()->stats().keepAliveFrames, frames);
    m_sim7->faults().setSilent(false);
    QVERIFY(waitUntil([d] { return d->status().online; }, 1000));
}

void TestServoCanDrive::watchdogStopsMotionWithoutKeepAlive()
{
    ServoCanDrive *d = drive(7);
    d->setJogLeaseMs(10000);
    DriveReply *r = d->jog(300);
    QVERIFY(waitFinished(r));
    QVERIFY2(r->ok(), qPrintable(errorText(r)));
    const quint64 trips = m_sim7->stats().watchdogTrips;
    // The drive's 2 s count starts at the last keep-alive it got: make sure that is now.
    const quint64 keepAlives = m_sim7->stats().keepAlives;
    QVERIFY(waitUntil([this, keepAlives] { return m_sim7->stats().keepAlives >= keepAlives + 2; }, 1000));
    QSignalSpy lost(d, &Drive::connectionLost);
    QElapsedTimer t;
    t.start();
    m_backend->close(); // no more keep-alive; nothing else stops the axis
    QVERIFY(!d->isJogging());
    QVERIFY(waitUntil([this] { return !m_sim7->motor().isMoving(); }, 3000));
    const qint64 stoppedAfter = t.elapsed();
    qInfo("the drive stopped %lld ms after the link was closed", static_cast<long long>(stoppedAfter));
    QVERIFY2(stoppedAfter > 1700 && stoppedAfter < 2500, "the 2 s watchdog");
    QCOMPARE(m_sim7->stats().watchdogTrips, trips + 1);
    QVERIFY(m_sim7->motor().isEnabled()); // it holds the shaft
    QVERIFY(!m_sim7->isHostOnline());
    QCOMPARE(lost.size(), 0); // a user's close is not a lost link
    // Reconnect: a drive at rest gets no keep-alive (no motion lease); the next motion
    // command brings one first.
    QVERIFY(openBackend());
    QVERIFY(waitUntil([this] { return m_backend->tracker()->isOnline(7); }, 3000));
    QVERIFY(!m_sim7->isHostOnline());
    d->setJogLeaseMs(300);
}

void TestServoCanDrive::busGoingAwayIsALostLink()
{
    ServoCanDrive *d = drive(1);
    QSignalSpy lost(m_backend.get(), &FamilyBackend::linkLost);
    QSignalSpy driveLost(d, &Drive::connectionLost);
    m_hub.reset(); // the process hosting the virtual bus went away
    QVERIFY(lost.wait(3000));
    QCOMPARE(lost.first().first().value<Error>().code, ErrorCode::LinkClosed);
    QCOMPARE(driveLost.size(), 1);
    QVERIFY(!m_backend->isOpen());
    QVERIFY(!d->status().online);
    QVERIFY(m_backend->tracker()->seenStations().isEmpty()); // keep-alive ended
    DriveReply *r = d->readAlarm();
    QVERIFY(waitFinished(r));
    QCOMPARE(r->error().code, ErrorCode::LinkClosed);
}

QTEST_GUILESS_MAIN(TestServoCanDrive)
#include "tst_servocandrive.moc"
