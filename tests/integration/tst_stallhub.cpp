// Stalls: the GUI thread blocked for a second must not delay what keeps an axis safe.
// DriveHub (the GUI's way to the drives: links and drives on its own I/O thread) talks to a
// simulated servo-can drive whose SimBench runs on a third thread; the test thread plays the
// GUI and is blocked on purpose (QThread::msleep: that is the point of the test).
//  - Keep-alive: during a move (the keep-alive goes with motion), the gaps between 0x08
//    frames, time-stamped where the simulator receives them, stay <= 150 ms (period 100 ms)
//    while the GUI thread sleeps for 1 s.
//  - Jog lease: renewed every 50 ms from a GUI timer the axis turns; when the GUI thread
//    blocks, the renewals stop and within 300 ms (+ margin) the I/O side puts a stop on the
//    wire; the motor decelerates; jogLeaseExpired and jogEnded reach the GUI afterwards.
#include <QtTest>

#include "tests/support/replywait.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/protocol/servocan/servocan.h"
#include "sim/bench/simbench.h"
#include "sim/bus/simcanbus.h"
#include "sim/servocan/simservocandrive.h"

#include <QMutex>
#include <QThread>

#include <chrono>

using namespace dd;
namespace sc = dd::servocan;

namespace {

qint64 steadyNs()
{
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

double ms(qint64 ns)
{
    return double(ns) / 1e6;
}

// A SimBench on its own thread, recording every host frame with a steady-clock stamp.
class SimThread
{
public:
    struct Rx
    {
        qint64 ns;
        CanFrameData frame;
    };

    ~SimThread()
    {
        if (m_bench)
            QMetaObject::invokeMethod(
                m_bench, [this] { delete m_bench; }, Qt::BlockingQueuedConnection);
        m_thread.quit();
        m_thread.wait();
    }

    Error start(const SimBenchOptions &options)
    {
        m_thread.setObjectName(QStringLiteral("sim"));
        m_thread.start();
        m_bench = new SimBench;
        m_bench->moveToThread(&m_thread);
        Error e;
        QMetaObject::invokeMethod(
            m_bench,
            [this, options, &e] {
                e = m_bench->start(options);
                if (e.isError())
                    return;
                m_settings = m_bench->clientSettings();
                QObject::connect(m_bench->canBus(), &SimCanBus::frameReceived, m_bench,
                                 [this](const CanFrameData &f, qint64) {
                                     QMutexLocker lock(&m_mutex);
                                     m_rx.append({steadyNs(), f});
                                 });
            },
            Qt::BlockingQueuedConnection);
        return e;
    }

    ConnectionSettings clientSettings() const { return m_settings; }

    // Runs `fn(drive)` on the simulator's thread and returns its result.
    template <typename Fn>
    auto onDrive(Fn fn)
    {
        decltype(fn(std::declval<SimServoCanDrive &>())) result{};
        QMetaObject::invokeMethod(
            m_bench,
            [this, &fn, &result] {
                auto *d = static_cast<SimServoCanDrive *>(m_bench->canBus()->device(0));
                result = fn(*d);
            },
            Qt::BlockingQueuedConnection);
        return result;
    }

    // Times (ns) at which the simulator received frames with this command byte.
    QList<qint64> times(sc::Command command) const
    {
        QMutexLocker lock(&m_mutex);
        QList<qint64> out;
        for (const Rx &r : m_rx)
            if (r.frame.data.size() == 8 && quint8(r.frame.data.at(1)) == quint8(command))
                out.append(r.ns);
        return out;
    }

private:
    QThread m_thread;
    SimBench *m_bench = nullptr;
    ConnectionSettings m_settings;
    mutable QMutex m_mutex;
    QList<Rx> m_rx;
};

// Turns a callback into a signal for QSignalSpy::wait.
class Done : public QObject
{
    Q_OBJECT
signals:
    void done();
};

using dd::test::waitUntil;

} // namespace

class TestStallHub : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void keepAliveSurvivesABlockedGuiThread();
    void jogLeaseStopsTheAxisWhenTheGuiBlocks();

private:
    int openConnection();
    DriveResult run(int id, const DriveHub::Operation &op);
    // run() once the drive's heartbeat was heard (the drive's status says online).
    DriveResult runWhenOnline(int id, const DriveHub::Operation &op);

    std::unique_ptr<SimThread> m_sim;
    std::unique_ptr<DriveHub> m_hub;
};

void TestStallHub::init()
{
    m_sim = std::make_unique<SimThread>();
    SimBenchOptions o;
    o.family = Family::ServoCan;
    o.can = QStringLiteral("virtualcan:auto"); // a private hub on a free port
    const Error e = m_sim->start(o);
    QVERIFY2(!e.isError(), qPrintable(e.message));
    m_hub = std::make_unique<DriveHub>();
}

void TestStallHub::cleanup()
{
    m_hub.reset();
    m_sim.reset();
}

int TestStallHub::openConnection()
{
    Done d;
    QSignalSpy spy(&d, &Done::done);
    int id = 0;
    Error error;
    m_hub->openConnection(m_sim->clientSettings(), [&](int i, const Error &e) {
        id = i;
        error = e;
        emit d.done();
    });
    if (!spy.wait(5000))
        return 0;
    if (error.isError())
        qWarning() << error.message;
    return id;
}

DriveResult TestStallHub::run(int id, const DriveHub::Operation &op)
{
    Done d;
    QSignalSpy spy(&d, &Done::done);
    DriveResult result;
    result.error = {ErrorCode::Timeout, QStringLiteral("no answer from the hub")};
    m_hub->run(id, 1, op, [&](const DriveResult &r) {
        result = r;
        emit d.done();
    });
    spy.wait(5000);
    return result;
}

DriveResult TestStallHub::runWhenOnline(int id, const DriveHub::Operation &op)
{
    waitUntil([&] { return run(id, [](Drive &d) { return d.readStatus(); }).status.online; }, 3000);
    return run(id, op);
}

void TestStallHub::keepAliveSurvivesABlockedGuiThread()
{
    const int id = openConnection();
    QVERIFY(id > 0);
    // The keep-alive goes with a motion (the motion lease): a long move holds it.
    const DriveResult move = runWhenOnline(id, [](Drive &d) { return d.moveRelative(50000000, 300); });
    QVERIFY2(move.ok(), qPrintable(move.error.message));
    QVERIFY(waitUntil([this] { return m_sim->times(sc::Command::KeepAlive).size() >= 3; }, 3000));

    const qint64 blockStart = steadyNs();
    QThread::msleep(1000); // the GUI thread is blocked
    const qint64 blockEnd = steadyNs();
    // One keep-alive after the block closes the last gap.
    QVERIFY(waitUntil([this, blockEnd] { return m_sim->times(sc::Command::KeepAlive).last() > blockEnd; }, 1000));

    const QList<qint64> t = m_sim->times(sc::Command::KeepAlive);
    // The guarantee is the gap (<= 150 ms, period 100 ms), from the last keep-alive before the
    // block to the first after it; a count would fail on one allowed late frame.
    double maxGap = 0;
    int during = 0;
    qint64 prev = -1;
    for (int k = 0; k < t.size(); ++k) {
        const qint64 x = t.at(k);
        if (k + 1 < t.size() && t.at(k + 1) < blockStart) // from the last one before the block on
            continue;
        if (x >= blockStart && x <= blockEnd)
            ++during;
        if (prev >= 0)
            maxGap = std::max(maxGap, ms(x - prev));
        prev = x;
    }
    qInfo("GUI thread blocked %.0f ms: %d keep-alives meanwhile, max gap %.1f ms", ms(blockEnd - blockStart), during,
          maxGap);
    QVERIFY2(prev > blockEnd, "the gap is measured across the whole block");
    QVERIFY2(maxGap <= 150, qPrintable(QStringLiteral("keep-alive gap %1 ms").arg(maxGap)));
    QVERIFY(m_sim->onDrive([](SimServoCanDrive &d) { return d.isHostOnline(); }));
    QVERIFY(m_sim->onDrive([](SimServoCanDrive &d) { return d.motor().isMoving(); }));
    QVERIFY(run(id, [](Drive &d) { return d.stop(); }).ok());
}

void TestStallHub::jogLeaseStopsTheAxisWhenTheGuiBlocks()
{
    const int id = openConnection();
    QVERIFY(id > 0);
    QVERIFY(runWhenOnline(id, [](Drive &d) { return d.readStatus(); }).ok());
    QSignalSpy expired(m_hub.get(), &DriveHub::jogLeaseExpired);
    QSignalSpy ended(m_hub.get(), &DriveHub::jogEnded);

    // Hold the jog button: renew every 50 ms from a GUI-thread timer.
    QTimer renew;
    renew.setTimerType(Qt::PreciseTimer);
    qint64 lastRenew = 0;
    connect(&renew, &QTimer::timeout, this, [&] {
        lastRenew = steadyNs(); // before the renewal leaves: the lease cannot end sooner than 300 ms after
        m_hub->renewJogLease(id, 1);
    });
    const DriveResult jog = run(id, [](Drive &d) { return d.jog(300); });
    QVERIFY2(jog.ok(), qPrintable(jog.error.message));
    renew.start(50);
    // Longer than the 300 ms lease: the renewals keep it turning.
    QElapsedTimer held;
    held.start();
    QVERIFY(waitUntil([&held] { return held.elapsed() >= 700; }, 2000));
    QVERIFY(qAbs(m_sim->onDrive([](SimServoCanDrive &d) { return d.motor().speedRpm(); }) - 300) < 1);
    QVERIFY(m_sim->times(sc::Command::Stop).isEmpty());
    QCOMPARE(expired.size(), 0);

    // The GUI thread blocks: the renew timer cannot fire.
    const qint64 lastBeforeBlock = lastRenew;
    QThread::msleep(700);
    renew.stop();
    const QList<qint64> stops = m_sim->times(sc::Command::Stop);
    QVERIFY2(!stops.isEmpty(), "the I/O thread must stop the axis while the GUI is blocked");
    const double delay = ms(stops.first() - lastBeforeBlock);
    qInfo("jog lease: stop on the wire %.1f ms after the last renewal", delay);
    // The guarantee: not before the 300 ms lease has run out, and on the wire within the lease
    // plus one keep-alive period (100 ms: one late timer or frame allowed).
    QVERIFY2(delay >= 299 && delay <= 300 + 100, qPrintable(QStringLiteral("stop after %1 ms").arg(delay)));
    // Decelerating already, at rest soon.
    QVERIFY(m_sim->onDrive([](SimServoCanDrive &d) { return d.motor().speedRpm(); }) < 300);
    QVERIFY(
        waitUntil([this] { return !m_sim->onDrive([](SimServoCanDrive &d) { return d.motor().isMoving(); }); }, 2000));
    // The GUI learns why once it runs again.
    QVERIFY(expired.size() == 1 || expired.wait(1000));
    QCOMPARE(expired.first().at(0).toInt(), id);
    QCOMPARE(expired.first().at(1).toInt(), 1);
    QVERIFY(ended.size() == 1 || ended.wait(1000));
    const JogEnd e = ended.first().at(2).value<JogEnd>();
    QCOMPARE(e.stoppedBy, JogEnd::StoppedBy::Command);
    QVERIFY(e.leaseExpired);
}

QTEST_GUILESS_MAIN(TestStallHub)
#include "tst_stallhub.moc"
