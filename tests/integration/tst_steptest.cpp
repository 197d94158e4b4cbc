// StepTest (core/tuning/steptest.h) against a simulated servo-can drive through the real
// host stack (ServoCanBackend: CanLink, station tracker, ServoCanDrive) on a private
// VirtualCanHub at 1 Mbit/s: refusals send nothing; a velocity step is captured, measured and
// goes back to its start; an alarm, STOP and a limit abort it with the axis stopped; a
// higher speed-loop gain measures a shorter rise and a larger overshoot through the link.
#include <QtTest>

#include "core/drive/servocan/servocanbackend.h"
#include "core/drive/servocan/servocandrive.h"
#include "core/drive/servocan/servocanstationtracker.h"
#include "core/params/parameterdictionary.h"
#include "core/tuning/steptest.h"
#include "sim/bus/simcanbus.h"
#include "sim/bus/virtualcanhub.h"
#include "sim/servocan/simservocandrive.h"
#include "tests/support/replywait.h"
#include "tests/support/simcanconnect.h"
#include "tests/support/timingscale.h"

#include <QElapsedTimer>
#include <memory>

using namespace dd;

namespace {

using dd::test::waitUntil;

StepLimits limits(double maxSpeed = 1000, qint64 maxTravel = 100000, double maxDuration = 3)
{
    StepLimits l;
    l.maxSpeed = maxSpeed;
    l.maxTravel = maxTravel;
    l.maxDurationS = maxDuration;
    return l;
}

StepSpec velocity(qint32 speed, double seconds)
{
    StepSpec s;
    s.kind = StepSpec::Kind::Velocity;
    s.speed = speed;
    s.durationS = seconds;
    return s;
}

} // namespace

class TestStepTest : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void cleanupTestCase();
    void init();

    void refusedWithoutLimitsSendsNothing();
    void velocityStepIsMeasuredAndReturns();
    void abortsOnAnAlarmWithTheAxisStopped();
    void abortsOnStopWithTheAxisStopped();
    void abortsWhenTheTravelLimitIsPassed();
    void destroyedMidTestStopsTheAxis();
    void abortsWhenTheSpeedLimitIsPassed();
    void aLostLinkSaysWhatStopsTheAxis();
    // Issue 26: a STOP from anywhere ends a test and nothing moves after it.
    void aStopAtTheDriveAbortsAVelocityStepAndNothingMovesAfter();
    void aStopAtTheDriveAbortsAPositionStep();
    void aStopAtTheDriveDuringTheReturnEndsIt();
    // Issue 26: limits are bounds, checked before motion.
    void aTestBeyondItsLimitsIsRefusedBeforeMotion();
    void aTravelTripStopsTheAxisInsideTheLimit();
    void anAlarmAtTheStartIsARefusal();
    void higherSpeedGainRisesFasterAndOvershootsMore();

private:
    bool write(const QList<ParameterWrite> &writes);
    StepResult run(StepTest &test, const StepSpec &spec, const StepLimits &l, int ms = 10000);

    std::unique_ptr<VirtualCanHub> m_hub;
    std::unique_ptr<SimCanBus> m_bus;
    SimServoCanDrive *m_sim = nullptr;
    std::unique_ptr<ServoCanBackend> m_backend;
    Drive *m_drive = nullptr;
};

void TestStepTest::initTestCase()
{
    m_hub = std::make_unique<VirtualCanHub>();
    QVERIFY(m_hub->start());
    m_bus = std::make_unique<SimCanBus>();
    m_sim = static_cast<SimServoCanDrive *>(m_bus->addDevice(std::make_unique<SimServoCanDrive>(1)));
    const QString busError = test::connectSimCanBus(m_bus.get(), m_hub->interfaceName(1));
    QVERIFY2(busError.isEmpty(), qPrintable(busError));
    m_backend = std::make_unique<ServoCanBackend>();
    ConnectionSettings cs;
    cs.family = Family::ServoCan;
    cs.can = QStringLiteral("virtualcan:") + m_hub->interfaceName(1);
    Error oe;
    QVERIFY2(m_backend->open(cs, nullptr, &oe), qPrintable(oe.message));
    QVERIFY(waitUntil([this] { return m_backend->tracker()->onlineStations() == QList<int>({1}); }, 3000));
    m_drive = m_backend->drive(1);
    QVERIFY(m_drive);
    // The simulator's dictionary: its "tuning" group names the loop gains (P60..P65).
    m_drive->setDictionary(
        std::make_shared<ParameterDictionary>(ParameterDictionary::bundledSimulator(Family::ServoCan)));
}

void TestStepTest::cleanupTestCase()
{
    m_backend.reset();
    m_bus.reset();
    m_hub.reset();
}

void TestStepTest::init()
{
    m_sim->motor().clearAlarm();
    m_sim->motor().stop();
    QVERIFY(waitUntil([this] { return !m_sim->motor().isMoving() && m_drive->status().alarmCode == 0; }, 3000));
}

StepResult TestStepTest::run(StepTest &test, const StepSpec &spec, const StepLimits &l, int ms)
{
    QSignalSpy finished(&test, &StepTest::finished);
    const Error e = test.start(spec, l);
    if (e) {
        qWarning("refused: %s", qPrintable(e.message));
        return {};
    }
    if (!finished.wait(ms) && finished.isEmpty())
        return {};
    return finished.first().first().value<StepResult>();
}

void TestStepTest::refusedWithoutLimitsSendsNothing()
{
    StepTest test(m_drive);
    QSignalSpy finished(&test, &StepTest::finished);
    const quint64 frames = m_sim->stats().framesForUs;
    StepLimits none;
    Error e = test.start(velocity(300, 0.2), none);
    QCOMPARE(e.code, ErrorCode::InvalidArgument);
    QVERIFY2(e.message.contains(QStringLiteral("maximum speed")), qPrintable(e.message));
    // Each limit on its own, and a step beyond a limit, is refused too.
    StepLimits l = limits();
    l.maxTravel = 0;
    QVERIFY(test.start(velocity(300, 0.2), l).message.contains(QStringLiteral("maximum travel")));
    l = limits();
    l.maxDurationS = 0;
    QVERIFY(test.start(velocity(300, 0.2), l).message.contains(QStringLiteral("maximum duration")));
    QVERIFY(test.start(velocity(1200, 0.2), limits()).message.contains(QStringLiteral("1200")));
    QVERIFY(test.start(velocity(300, 5), limits()).code == ErrorCode::InvalidArgument);
    QVERIFY(!test.isRunning());
    QCoreApplication::processEvents();
    QCOMPARE(finished.size(), 0);
    // The keep-alives of the link go on; nothing addressed to the drive came from the test.
    QVERIFY(m_sim->stats().framesForUs - frames <= 2);
    QCOMPARE(m_sim->stats().motionCommands, m_sim->stats().motionCommands);
}

void TestStepTest::velocityStepIsMeasuredAndReturns()
{
    const quint64 moves = m_sim->stats().motionCommands;
    StepTest test(m_drive);
    const StepResult r = run(test, velocity(300, 0.25), limits());
    QVERIFY2(r.completed(), qPrintable(r.reason + QLatin1Char(' ') + r.stopNote));
    QVERIFY(m_sim->stats().motionCommands > moves);
    QVERIFY(r.stopConfirmed);
    QVERIFY(r.hasRun);
    QVERIFY2(r.returnedToStart, qPrintable(r.stopNote));
    QVERIFY(std::abs(m_sim->motor().position() - r.startPosition) <= 1);
    const TuningRun &run = r.run;
    QCOMPARE(run.test, QStringLiteral("velocity-step"));
    QCOMPARE(run.capture.triggerSource, QStringLiteral("motion"));
    QVERIFY(run.capture.preTriggerSamples > 0);
    QVERIFY(run.capture.channels.contains(QStringLiteral("speed")));
    QCOMPARE(run.tuning.size(), 6);
    QVERIFY(run.metrics.riseTime.value.has_value());
    QVERIFY(*run.metrics.riseTime.value > 0.0 && *run.metrics.riseTime.value < 0.1);
    QVERIFY(run.metrics.overshoot.value.has_value());
    qInfo("velocity step 300 r/min: %d samples, interval %.3f ms, rise %.1f ms, overshoot %.1f %%",
          int(run.capture.time.size()), run.capture.interval.mean * 1e3, *run.metrics.riseTime.value * 1e3,
          *run.metrics.overshoot.value);
}

void TestStepTest::abortsOnAnAlarmWithTheAxisStopped()
{
    StepTest test(m_drive);
    QSignalSpy finished(&test, &StepTest::finished);
    QVERIFY(!test.start(velocity(300, 1.0), limits()));
    QVERIFY(
        waitUntil([&] { return test.phase() == StepTest::Phase::Moving && m_sim->motor().speedRpm() > 200; }, 3000));
    m_sim->injectAlarm(9);
    QVERIFY(finished.wait(5000));
    const StepResult r = finished.first().first().value<StepResult>();
    QCOMPARE(r.outcome, StepResult::Outcome::Aborted);
    QCOMPARE(r.abortCause, QStringLiteral("alarm"));
    QCOMPARE(r.error.driveCode, 9);
    QVERIFY2(r.stopConfirmed, qPrintable(r.stopNote));
    QVERIFY(!r.returnedToStart); // an aborted test does not move again
    QVERIFY(!m_sim->motor().isMoving());
}

void TestStepTest::abortsOnStopWithTheAxisStopped()
{
    StepTest test(m_drive);
    QSignalSpy finished(&test, &StepTest::finished);
    QVERIFY(!test.start(velocity(-400, 1.0), limits()));
    QVERIFY(
        waitUntil([&] { return test.phase() == StepTest::Phase::Moving && m_sim->motor().speedRpm() < -300; }, 3000));
    // STOP from anywhere (the GUI's STOP button stops the drive itself).
    DriveReply *stop = m_drive->stop();
    QVERIFY(finished.wait(5000));
    QVERIFY(test::waitFinished(stop, 2000));
    const StepResult r = finished.first().first().value<StepResult>();
    QCOMPARE(r.outcome, StepResult::Outcome::Aborted);
    QCOMPARE(r.abortCause, QStringLiteral("stop"));
    QVERIFY2(r.stopConfirmed, qPrintable(r.stopNote));
    QCOMPARE(r.stoppedBy, QStringLiteral("command"));
    QVERIFY(!m_sim->motor().isMoving());
}

void TestStepTest::abortsWhenTheTravelLimitIsPassed()
{
    StepTest test(m_drive);
    // 500 r/min = 83 counts/ms at 10000 counts/rev: 2000 counts are passed within 30 ms. Told
    // 100 counts/rev, the test predicts 850 counts and starts; the travel watch trips.
    StepSpec spec = velocity(500, 1.0);
    spec.countsPerRev = 100;
    const StepResult r = run(test, spec, limits(1000, 2000, 3));
    QCOMPARE(r.outcome, StepResult::Outcome::Aborted);
    QCOMPARE(r.abortCause, QStringLiteral("travel-limit"));
    QVERIFY2(r.stopConfirmed, qPrintable(r.stopNote));
    QVERIFY(!m_sim->motor().isMoving());
}

void TestStepTest::destroyedMidTestStopsTheAxis()
{
    QSignalSpy expired(m_drive, &Drive::jogLeaseExpired);
    auto *test = new StepTest(m_drive);
    QVERIFY(!test->start(velocity(300, 1.0), limits()));
    QVERIFY(
        waitUntil([&] { return test->phase() == StepTest::Phase::Moving && m_sim->motor().speedRpm() > 200; }, 3000));
    delete test; // a closed tab: its own stop, not the lease running out
    QVERIFY(waitUntil([this] { return !m_sim->motor().isMoving(); }, 3000));
    QCOMPARE(expired.size(), 0);
}

void TestStepTest::abortsWhenTheSpeedLimitIsPassed()
{
    // A stiff loop on a true step overshoots 300 r/min by ~25 %: above a limit of 330.
    QVERIFY(write({{60, 60}, {64, 1000}, {65, 0}}));
    StepTest test(m_drive);
    const StepResult r = run(test, velocity(300, 0.5), limits(330));
    // At the confirmed stop the shaft is at rest; the stiff loop (no integral action) may
    // still hold it a count or so off its reference until the gains are put back (it failed
    // 1 full ctest run in 4 on a busy machine when checked at once).
    const double speedAtStop = m_sim->motor().speedRpm();
    QVERIFY(write({{60, 30}, {64, 6}, {65, 100}}));
    QCOMPARE(r.outcome, StepResult::Outcome::Aborted);
    QCOMPARE(r.abortCause, QStringLiteral("speed-limit"));
    QVERIFY2(r.reason.contains(QStringLiteral("above the maximum speed 330")), qPrintable(r.reason));
    QVERIFY2(r.stopConfirmed, qPrintable(r.stopNote));
    QVERIFY2(std::abs(speedAtStop) < 5, qPrintable(QString::number(speedAtStop)));
    QVERIFY(waitUntil([this] { return !m_sim->motor().isMoving(); }, 1000));
}

void TestStepTest::aLostLinkSaysWhatStopsTheAxis()
{
    // The link goes away mid-step (as DriveConnection reports it): no stop can be sent; the
    // result says the drive's own watchdog stops the axis (servo-can has one).
    StepTest test(m_drive);
    QSignalSpy finished(&test, &StepTest::finished);
    QVERIFY(!test.start(velocity(200, 1.0), limits()));
    QVERIFY(waitUntil([&] { return test.phase() == StepTest::Phase::Moving; }, 3000));
    test.linkLost({ErrorCode::LinkClosed, QStringLiteral("adapter unplugged")});
    QCOMPARE(finished.size(), 1);
    const StepResult r = finished.first().first().value<StepResult>();
    QCOMPARE(r.outcome, StepResult::Outcome::Aborted);
    QCOMPARE(r.abortCause, QStringLiteral("link-lost"));
    QCOMPARE(r.stoppedBy, QStringLiteral("drive-watchdog"));
    QVERIFY(!r.stopConfirmed);
    QVERIFY2(r.stopNote.contains(QStringLiteral("watchdog")), qPrintable(r.stopNote));
    // Here the link is in fact still up: the jog lease, no longer renewed, stops the axis.
    QVERIFY(waitUntil([this] { return !m_sim->motor().isMoving(); }, 3000));
}

namespace {
// The drive's motion commands stay as they are for `ms`: nothing was sent after the test.
bool noMotionSentFor(SimServoCanDrive *sim, int ms)
{
    const quint64 before = sim->stats().motionCommands;
    QTest::qWait(ms);
    return sim->stats().motionCommands == before;
}
} // namespace

void TestStepTest::aStopAtTheDriveAbortsAVelocityStepAndNothingMovesAfter()
{
    // The drive is stopped by something else than this program (its panel, a PLC, another
    // master): its speed command falls to 0. The test must see it, abort with that cause,
    // and never drive the axis back to its start.
    StepTest test(m_drive);
    QSignalSpy finished(&test, &StepTest::finished);
    QVERIFY(!test.start(velocity(300, 1.0), limits()));
    QVERIFY(
        waitUntil([&] { return test.phase() == StepTest::Phase::Moving && m_sim->motor().speedRpm() > 250; }, 3000));
    QTest::qWait(100);
    m_sim->motor().stop();
    QVERIFY(finished.wait(5000));
    const StepResult r = finished.first().first().value<StepResult>();
    QCOMPARE(r.outcome, StepResult::Outcome::Aborted);
    QCOMPARE(r.abortCause, QStringLiteral("external-stop"));
    QVERIFY2(r.reason.contains(QStringLiteral("another master or at the drive")), qPrintable(r.reason));
    QVERIFY(!r.returnedToStart);
    QVERIFY2(r.stopConfirmed, qPrintable(r.stopNote));
    const qint64 at = m_sim->motor().position();
    QVERIFY(std::abs(double(at - r.startPosition)) > 1000); // it had gone some way
    QVERIFY(noMotionSentFor(m_sim, 600));
    QCOMPARE(m_sim->motor().position(), at); // and stays there
    // The data up to the abort is kept, marked aborted.
    QVERIFY(r.hasRun);
    QCOMPARE(r.run.outcome, QStringLiteral("aborted"));
    QCOMPARE(r.run.abortCause, QStringLiteral("external-stop"));
    QVERIFY(!r.run.metrics.steadyStateError.value); // not a measured step
    QVERIFY(r.run.capture.time.size() > 50);
}

void TestStepTest::aStopAtTheDriveAbortsAPositionStep()
{
    StepTest test(m_drive);
    QSignalSpy finished(&test, &StepTest::finished);
    StepSpec spec;
    spec.kind = StepSpec::Kind::Position;
    spec.speed = 300;
    spec.distance = 60000;
    QVERIFY(!test.start(spec, limits(1000, 100000, 5)));
    QVERIFY(
        waitUntil([&] { return test.phase() == StepTest::Phase::Stopping && m_sim->motor().speedRpm() > 250; }, 3000));
    m_sim->motor().stop();
    QVERIFY(finished.wait(5000));
    const StepResult r = finished.first().first().value<StepResult>();
    QCOMPARE(r.abortCause, QStringLiteral("external-stop"));
    QVERIFY2(r.reason.contains(QStringLiteral("short of its target")), qPrintable(r.reason));
    QVERIFY(!r.returnedToStart);
    const qint64 at = m_sim->motor().position();
    QVERIFY(noMotionSentFor(m_sim, 600));
    QCOMPARE(m_sim->motor().position(), at);
}

void TestStepTest::aStopAtTheDriveDuringTheReturnEndsIt()
{
    StepTest test(m_drive);
    QSignalSpy finished(&test, &StepTest::finished);
    QStringList phases;
    connect(&test, &StepTest::progress, this, [&](StepTest::Phase p, const QString &m) {
        if (p == StepTest::Phase::Returning)
            phases << m;
    });
    QVERIFY(!test.start(velocity(300, 0.6), limits()));
    QVERIFY(waitUntil(
        [&] { return test.phase() == StepTest::Phase::Returning && std::abs(m_sim->motor().speedRpm()) > 250; }, 5000));
    // The way back was announced before it started, as a motion.
    QCOMPARE(phases.size(), 1);
    QVERIFY2(phases.first().contains(QStringLiteral("STOP stops it")), qPrintable(phases.first()));
    m_sim->motor().stop();
    QVERIFY(finished.wait(5000));
    const StepResult r = finished.first().first().value<StepResult>();
    QCOMPARE(r.abortCause, QStringLiteral("external-stop"));
    QVERIFY(!r.returnedToStart);
    const qint64 at = m_sim->motor().position();
    QVERIFY(std::abs(double(at - r.startPosition)) > 1000);
    QVERIFY(noMotionSentFor(m_sim, 600));
    QCOMPARE(m_sim->motor().position(), at);
}

void TestStepTest::aTestBeyondItsLimitsIsRefusedBeforeMotion()
{
    const quint64 moves = m_sim->stats().motionCommands;
    StepTest test(m_drive);
    // The test: 300 r/min for 2 s (~100,000 counts) with 1000 counts of travel.
    Error e = test.start(velocity(300, 2.0), limits(500, 1000, 4));
    QCOMPARE(e.code, ErrorCode::OutOfRange);
    QVERIFY2(e.message.contains(QStringLiteral("beyond the maximum travel 1000")), qPrintable(e.message));
    // Fits at full speed (25,000 counts) but not with its stop at P64's 6 r/min/ms (+1250):
    // refused once the deceleration is read, before any motion.
    QSignalSpy finished(&test, &StepTest::finished);
    QVERIFY(!test.start(velocity(300, 0.5), limits(500, 25500, 4)));
    QVERIFY(finished.wait(5000));
    const StepResult r = finished.first().first().value<StepResult>();
    QCOMPARE(r.outcome, StepResult::Outcome::Failed);
    QCOMPARE(r.abortCause, QStringLiteral("refused"));
    QCOMPARE(r.error.code, ErrorCode::OutOfRange);
    QVERIFY2(r.reason.contains(QStringLiteral("P64 6")), qPrintable(r.reason));
    QVERIFY(!r.moved);
    // A position step that needs more than its maximum duration.
    StepSpec pos;
    pos.kind = StepSpec::Kind::Position;
    pos.speed = 300;
    pos.distance = 60000;
    e = test.start(pos, limits(1000, 100000, 0.5));
    QCOMPARE(e.code, ErrorCode::OutOfRange);
    QVERIFY2(e.message.contains(QStringLiteral("maximum duration of 0.5 s")), qPrintable(e.message));
    QCOMPARE(m_sim->stats().motionCommands, moves);
}

void TestStepTest::aTravelTripStopsTheAxisInsideTheLimit()
{
    // Told 100 counts per revolution (the drive has 10000), the prediction is far too short
    // and the test starts; the travel watch trips at limit - stopping distance (measured
    // speed, P64's deceleration), and the axis comes to rest inside the limit.
    // A slower build runs it slower (tests/support/timingscale.h): a stall of the machine at
    // the trip carries the axis on at the speed it has.
    StepTest test(m_drive);
    StepSpec spec = velocity(500 / dd::test::kTimingScale, 1.0);
    spec.countsPerRev = 100;
    const StepResult r = run(test, spec, limits(1000, 3000, 3));
    QCOMPARE(r.outcome, StepResult::Outcome::Aborted);
    QCOMPARE(r.abortCause, QStringLiteral("travel-limit"));
    QVERIFY2(r.stopConfirmed, qPrintable(r.stopNote));
    qInfo("travel trip: farthest %lld of 3000, at rest %lld from the start", r.farthest,
          r.endPosition - r.startPosition);
    QVERIFY2(r.farthest <= 3000, qPrintable(r.stopNote));
    QVERIFY(std::abs(double(m_sim->motor().position() - r.startPosition)) <= 3000);
    QVERIFY2(r.stopNote.contains(QStringLiteral("of the maximum travel 3000")), qPrintable(r.stopNote));
    QVERIFY(r.hasRun);
    QCOMPARE(r.run.outcome, QStringLiteral("aborted"));
}

void TestStepTest::anAlarmAtTheStartIsARefusal()
{
    const quint64 moves = m_sim->stats().motionCommands;
    m_sim->injectAlarm(3);
    StepTest test(m_drive);
    const StepResult r = run(test, velocity(300, 0.5), limits());
    QCOMPARE(r.outcome, StepResult::Outcome::Failed);
    QCOMPARE(r.abortCause, QStringLiteral("refused"));
    QVERIFY2(r.reason.contains(QStringLiteral("Alarm 3 is active: clear it first")), qPrintable(r.reason));
    QVERIFY(!r.moved);
    QCOMPARE(m_sim->stats().motionCommands, moves);
    m_sim->injectAlarm(0);
    // The status read learnt alarm 3; read the alarm again to learn that it is gone.
    QVERIFY(waitUntil(
        [this] {
            DriveReply *r = m_drive->readAlarm();
            test::waitFinished(r, 1000);
            return m_drive->status().alarmCode == 0;
        },
        3000));
}

bool TestStepTest::write(const QList<ParameterWrite> &writes)
{
    DriveReply *r = m_drive->writeParameters(writes);
    return test::waitFinished(r, 3000) && r->ok();
}

void TestStepTest::higherSpeedGainRisesFasterAndOvershootsMore()
{
    // The loop as the test has it: the speed command a true step (acceleration P64
    // at its most, no torque feed-forward P65), a low integral gain (P61 = 10 1/s, so that
    // the overshoot is the proportional gain's), speed-loop gain P60 20 Hz then 50 Hz, the
    // step measured through the link at the capture's rate (speed, and position for the
    // travel limit: ~1 kHz on servo-can at 1 Mbit/s on a loaded machine).
    QVERIFY(write({{61, 10}, {64, 1000}, {65, 0}}));
    StepSpec spec = velocity(180, 0.15);
    spec.channels = {QStringLiteral("speed")};
    QList<StepMetrics> measured;
    for (int gain : {20, 50}) {
        QVERIFY(write({{60, gain}}));
        StepMetrics m;
        // A stall of the loaded machine during a rise of a few ms makes it unresolvable (the
        // metric says so); take the step again then.
        for (int attempt = 0; attempt < 8 && !m.riseTime.value; ++attempt) {
            StepTest test(m_drive);
            const StepResult r = run(test, spec, limits());
            QVERIFY2(r.completed(), qPrintable(r.reason));
            m = r.run.metrics;
            QCOMPARE(r.run.tuning.at(0).value, gain); // the snapshot is what the drive had
        }
        // On a loaded 2-core machine the client stalls for 2-5 ms every few ms (median
        // interval ~1 ms): a 3 ms rise then stays unresolvable, as the metric says. The model
        // itself is tested in tst_servoloop; here the chain is asserted when it resolves.
        if (!m.riseTime.value && write({{60, 30}, {61, 30}, {64, 6}, {65, 100}}))
            QSKIP(qPrintable(QStringLiteral("P60 %1 Hz: %2").arg(gain).arg(m.riseTime.reason)));
        QVERIFY(m.overshoot.value);
        qInfo("P60 %d Hz: rise %.2f ms, overshoot %.1f %%, settling (2 %%) %s ms, interval %.3f ms", gain,
              *m.riseTime.value * 1e3, *m.overshoot.value,
              m.settlingTime2.value ? qPrintable(QString::number(*m.settlingTime2.value * 1e3, 'f', 1)) : "-",
              *m.sampleInterval.value * 1e3);
        measured << m;
    }
    QVERIFY(write({{60, 30}, {61, 30}, {64, 6}, {65, 100}}));
    QVERIFY(*measured.at(1).riseTime.value < *measured.at(0).riseTime.value);
    QVERIFY(*measured.at(1).overshoot.value > *measured.at(0).overshoot.value);
}

QTEST_GUILESS_MAIN(TestStepTest)
#include "tst_steptest.moc"
