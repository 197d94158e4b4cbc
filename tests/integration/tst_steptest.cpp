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

#include <QElapsedTimer>
#include <memory>

using namespace dd;

namespace {

bool waitUntil(const std::function<bool()> &cond, int ms)
{
    QElapsedTimer t;
    t.start();
    while (!cond() && t.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    return cond();
}

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

private:
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
    // 500 r/min = 83 counts/ms at 10000 counts/rev: 2000 counts are passed within 30 ms.
    const StepResult r = run(test, velocity(500, 1.0), limits(1000, 2000, 3));
    QCOMPARE(r.outcome, StepResult::Outcome::Aborted);
    QCOMPARE(r.abortCause, QStringLiteral("travel-limit"));
    QVERIFY2(r.stopConfirmed, qPrintable(r.stopNote));
    QVERIFY(!m_sim->motor().isMoving());
}

QTEST_GUILESS_MAIN(TestStepTest)
#include "tst_steptest.moc"
