#include <QtTest>

#include "sim/motor/motormodel.h"

#include <cmath>

using namespace dd;

namespace {
constexpr double Dt = MotorModel::StepSeconds;

// Steps the model millisecond by millisecond, checking the accel/decel limits on every step;
// returns the number of steps taken until `done` (or -1 after maxSteps).
template <class Done>
int stepChecked(MotorModel &m, Done done, int maxSteps, double *maxAbsSpeed = nullptr)
{
    const double a = m.config().acceleration;
    const double d = m.config().deceleration;
    for (int i = 1; i <= maxSteps; ++i) {
        const double v0 = m.speed();
        m.advanceTo(m.time() + Dt);
        const double v1 = m.speed();
        const double dv = std::abs(v1 - v0);
        const bool growing = std::abs(v1) > std::abs(v0) && (v0 == 0.0 || (v0 > 0) == (v1 > 0));
        const double limit = (growing ? a : d) * Dt;
        if (dv > limit * (1.0 + 1e-9) + 1e-9) {
            qWarning("step %d: speed %g -> %g exceeds %s limit %g", i, v0, v1, growing ? "accel" : "decel", limit);
            return -2;
        }
        if (maxAbsSpeed)
            *maxAbsSpeed = std::max(*maxAbsSpeed, std::abs(v1));
        if (done())
            return i;
    }
    return -1;
}

MotorModel::Config quietConfig()
{
    MotorModel::Config c;
    c.acceleration = 1.0e6;
    c.deceleration = 5.0e5;
    return c;
}
} // namespace

class TestMotorModel : public QObject
{
    Q_OBJECT
private slots:
    void startsAtRestDisabled()
    {
        MotorModel m;
        QVERIFY(!m.isEnabled());
        QCOMPARE(m.position(), 0);
        QCOMPARE(m.speed(), 0.0);
        QCOMPARE(m.current(), 0.0);
        QCOMPARE(m.temperature(), m.config().ambientTemperature);
        QVERIFY(!m.runSpeed(1000));
        QVERIFY(!m.moveRelative(1000, 1000));
        QCOMPARE(m.mode(), MotorModel::Mode::Idle);
    }

    void speedLoopHonoursLimits()
    {
        MotorModel m(quietConfig());
        QVERIFY(m.enable());
        QVERIFY(m.runSpeed(100000));
        // 0 -> 100000 counts/s at 1e6 counts/s² takes 100 ms
        const int up = stepChecked(
            m, [&] { return m.speed() == 100000.0; }, 1000);
        QCOMPARE(up, 100);
        QCOMPARE(m.acceleration(), 1.0e6);
        // reverse: 100 ms... no: decelerate 200 ms at 5e5, then accelerate 100 ms at 1e6
        QVERIFY(m.runSpeed(-100000));
        const int reverse = stepChecked(
            m, [&] { return m.speed() == -100000.0; }, 1000);
        QCOMPARE(reverse, 300);
        // above the maximum speed: clamped
        QVERIFY(m.runSpeed(1e9));
        QCOMPARE(m.targetSpeed(), m.config().maxSpeed);
        QVERIFY(stepChecked(
                    m, [&] { return m.speed() == m.config().maxSpeed; }, 5000)
                > 0);
        QCOMPARE(m.speedRpm(), m.config().maxSpeed * 60.0 / m.config().countsPerRev);
    }

    void moveEndsExactlyOnTarget_data()
    {
        QTest::addColumn<qint64>("start");
        QTest::addColumn<qint64>("target");
        QTest::addColumn<double>("speed");
        QTest::newRow("one count") << qint64(0) << qint64(1) << 10000.0;
        QTest::newRow("seven") << qint64(0) << qint64(7) << 10000.0;
        QTest::newRow("triangle") << qint64(0) << qint64(1000) << 200000.0;
        QTest::newRow("trapezoid") << qint64(0) << qint64(123457) << 200000.0;
        QTest::newRow("negative") << qint64(500) << qint64(-49999) << 150000.0;
        QTest::newRow("slow") << qint64(0) << qint64(333) << 1000.0;
        QTest::newRow("far") << qint64(-1000000) << qint64(2000000) << 500000.0;
    }
    void moveEndsExactlyOnTarget()
    {
        QFETCH(qint64, start);
        QFETCH(qint64, target);
        QFETCH(double, speed);
        MotorModel m(quietConfig());
        m.setPosition(start);
        QVERIFY(m.enable());
        QVERIFY(m.moveAbsolute(target, speed));
        QCOMPARE(m.targetPosition(), target);
        const double dir = target > start ? 1.0 : -1.0;
        double last = m.positionExact();
        bool monotonic = true;
        double peak = 0.0;
        const int steps = stepChecked(
            m,
            [&] {
                if ((m.positionExact() - last) * dir < -1e-9)
                    monotonic = false;
                last = m.positionExact();
                return !m.isMoving();
            },
            200000, &peak);
        QVERIFY2(steps > 0, "move did not finish within its limits");
        QCOMPARE(m.position(), target);
        QCOMPARE(m.positionExact(), static_cast<double>(target));
        QCOMPARE(m.speed(), 0.0);
        QCOMPARE(m.mode(), MotorModel::Mode::Idle);
        QVERIFY2(monotonic, "the move overshot or reversed");
        QVERIFY(peak <= speed * (1 + 1e-9));

        // Duration close to the ideal trapezoid / triangle.
        const double dist = std::abs(static_cast<double>(target - start));
        const double a = m.config().acceleration, d = m.config().deceleration;
        const double vPeak = std::min(speed, std::sqrt(2 * dist * a * d / (a + d)));
        const double ideal = vPeak / a + vPeak / d + (dist - vPeak * vPeak / (2 * a) - vPeak * vPeak / (2 * d)) / vPeak;
        QVERIFY2(std::abs(steps * Dt - ideal) <= 0.004 + 0.01 * ideal,
                 qPrintable(QStringLiteral("took %1 s, ideal %2 s").arg(steps * Dt).arg(ideal)));
    }

    void relativeMoveAndSpeedChange()
    {
        MotorModel m(quietConfig());
        m.setPosition(1000);
        QVERIFY(m.enable());
        QVERIFY(m.moveRelative(-60000, 100000));
        QCOMPARE(m.targetPosition(), -59000);
        m.advanceTo(0.1);
        m.setMoveSpeed(20000); // slower mid-move: decelerates within its limit
        double peak = 0.0;
        QVERIFY(stepChecked(
                    m, [&] { return !m.isMoving(); }, 100000, &peak)
                > 0);
        QCOMPARE(m.position(), -59000);
    }

    void targetChangeMidMoveReverses()
    {
        MotorModel m(quietConfig());
        QVERIFY(m.enable());
        QVERIFY(m.moveAbsolute(100000, 200000));
        m.advanceTo(0.2);
        QVERIFY(m.speed() > 0);
        const qint64 here = m.position();
        QVERIFY(m.moveAbsolute(here, 200000)); // must brake, overshoot and come back
        QVERIFY(stepChecked(
                    m, [&] { return !m.isMoving(); }, 100000)
                > 0);
        QCOMPARE(m.position(), here);
    }

    void stopDecelerates()
    {
        MotorModel m(quietConfig());
        QVERIFY(m.enable());
        QVERIFY(m.runSpeed(-100000));
        m.advanceTo(0.5);
        QCOMPARE(m.speed(), -100000.0);
        m.stop();
        QCOMPARE(m.mode(), MotorModel::Mode::Stopping);
        QCOMPARE(m.targetSpeed(), 0.0);
        // 100000 / 5e5 = 200 ms
        QCOMPARE(stepChecked(
                     m, [&] { return m.speed() == 0.0; }, 1000),
                 200);
        QCOMPARE(m.mode(), MotorModel::Mode::Idle);
        QVERIFY(m.isEnabled());
        const qint64 held = m.position();
        m.advanceTo(m.time() + 1.0);
        QCOMPARE(m.position(), held);
    }

    void emergencyStopIsImmediate()
    {
        MotorModel m(quietConfig());
        QVERIFY(m.enable());
        QVERIFY(m.runSpeed(200000));
        m.advanceTo(0.5);
        const qint64 at = m.position();
        m.emergencyStop();
        QCOMPARE(m.speed(), 0.0);
        QVERIFY(!m.isMoving());
        QVERIFY(m.isEnabled());
        m.advanceTo(0.6);
        QCOMPARE(m.position(), at);
    }

    void disableCoastsWithFriction()
    {
        MotorModel::Config c = quietConfig();
        c.coulombFriction = 0.01;
        c.viscousFriction = 1e-5;
        c.loadTorque = 0.0;
        MotorModel m(c);
        QVERIFY(m.enable());
        QVERIFY(m.runSpeed(100000));
        m.advanceTo(0.5);
        m.disable();
        QVERIFY(!m.isEnabled());
        QVERIFY(!m.runSpeed(1000));
        m.advanceTo(0.51);
        QCOMPARE(m.current(), 0.0);
        QCOMPARE(m.torque(), 0.0);
        // friction alone brakes: (Tc + B·ω) / J, converted to counts/s²
        const double toCounts = c.countsPerRev / (2 * M_PI);
        const double decel = (c.coulombFriction + c.viscousFriction * 100000 / toCounts) / c.inertia * toCounts;
        QVERIFY2(std::abs((100000.0 - m.speed()) - decel * 0.01) < 0.01 * decel * 0.01,
                 qPrintable(QString::number(m.speed())));
        double previous = m.speed();
        bool decreasing = true;
        for (int i = 0; i < 60000 && m.speed() > 0.0; ++i) {
            m.advanceTo(m.time() + Dt);
            decreasing = decreasing && m.speed() <= previous;
            previous = m.speed();
        }
        QVERIFY(decreasing);
        QCOMPARE(m.speed(), 0.0);
        // re-enabling holds again
        QVERIFY(m.enable());
        QVERIFY(m.current() != 0.0 || m.config().loadTorque == 0.0);
    }

    void alarmDisablesAndStops()
    {
        MotorModel m(quietConfig());
        QVERIFY(m.enable());
        QVERIFY(m.moveRelative(1000000, 200000));
        m.advanceTo(0.3);
        m.injectAlarm(0x21);
        QCOMPARE(m.alarmCode(), 0x21);
        QVERIFY(!m.isEnabled());
        QVERIFY(!m.enable());
        QVERIFY(!m.moveRelative(10, 10));
        m.advanceTo(30.0);
        QCOMPARE(m.speed(), 0.0);
        QVERIFY(m.position() < 1000000);
        m.clearAlarm();
        QCOMPARE(m.alarmCode(), 0);
        QVERIFY(!m.isEnabled()); // clearing does not re-enable
        QVERIFY(m.enable());
    }

    void torqueCurrentAndFollowingErrorFromAcceleration()
    {
        MotorModel::Config c = quietConfig();
        c.currentNoise = 0.0;
        c.positionErrorNoise = 0.0;
        MotorModel m(c);
        QVERIFY(m.enable());
        m.advanceTo(0.01);
        const double holding = m.current();
        QCOMPARE(holding, c.loadTorque / c.torqueConstant);
        QCOMPARE(m.positionError(), 0);
        QVERIFY(m.runSpeed(100000));
        m.advanceTo(0.05); // accelerating, at 40000 counts/s
        const double accelSpeed = m.speed();
        const double accelCurrent = m.current();
        const qint64 accelError = m.positionError();
        m.advanceTo(1.0); // cruising at 100000 counts/s
        const double cruiseCurrent = m.current();
        const qint64 cruiseError = m.positionError();
        QVERIFY(accelCurrent > cruiseCurrent);
        QVERIFY(cruiseCurrent > holding);  // friction
        QVERIFY(accelError > cruiseError); // although slower
        QVERIFY(cruiseError > 0);
        QCOMPARE(m.commandPosition(), m.position() + cruiseError);
        const double toRad = 2 * M_PI / c.countsPerRev;
        const double expectedTorque = c.inertia * 1e6 * toRad + c.loadTorque + c.viscousFriction * accelSpeed * toRad
            + c.coulombFriction;
        QVERIFY(qFuzzyCompare(accelCurrent, expectedTorque / c.torqueConstant));
        QVERIFY(qFuzzyCompare(m.torquePercent(), 100.0 * m.torque() / c.ratedTorque));
        m.stop();
        m.advanceTo(1.1); // decelerating: the inertia now helps
        QVERIFY(m.current() < cruiseCurrent);
    }

    void busVoltageRippleAndSag()
    {
        MotorModel::Config c = quietConfig();
        c.voltageNoise = 0.0;
        MotorModel m(c);
        double lo = 1e9, hi = -1e9;
        for (int i = 1; i <= 20; ++i) {
            m.advanceTo(i * Dt);
            lo = std::min(lo, m.busVoltage());
            hi = std::max(hi, m.busVoltage());
        }
        QVERIFY(hi - lo > 1.0 * c.busRipple);
        QVERIFY(hi <= c.busVoltageNominal + c.busRipple + 1e-9);
        QVERIFY(lo >= c.busVoltageNominal - c.busRipple - 1e-9);
        c.loadTorque = 3.0; // 6 A
        m.setConfig(c);
        QVERIFY(m.enable());
        m.advanceTo(0.1);
        QVERIFY(m.busVoltage() < c.busVoltageNominal - 6 * c.busSagPerAmp + c.busRipple + 1e-9);
    }

    void temperatureRisesWithCurrentAndCools()
    {
        MotorModel::Config c = quietConfig();
        c.loadTorque = 1.0; // 2 A -> 8 W -> +24 K steady state
        MotorModel m(c);
        QVERIFY(m.enable());
        m.advanceTo(c.thermalTimeConstant); // one time constant: 63 %
        const double rise = m.temperature() - c.ambientTemperature;
        QVERIFY2(std::abs(rise - 24.0 * (1 - std::exp(-1.0))) < 0.5, qPrintable(QString::number(rise)));
        m.advanceTo(10 * c.thermalTimeConstant);
        QVERIFY(std::abs(m.temperature() - (c.ambientTemperature + 24.0)) < 0.1);
        m.disable();
        m.advanceTo(20 * c.thermalTimeConstant);
        QVERIFY(std::abs(m.temperature() - c.ambientTemperature) < 0.1);
    }

    void homing()
    {
        MotorModel m(quietConfig());
        m.setPosition(12345);
        QVERIFY(!m.startHoming(-5000, 50000)); // disabled
        QVERIFY(m.enable());
        QVERIFY(m.startHoming(-5000, 50000, 100));
        QVERIFY(m.isHoming());
        QVERIFY(stepChecked(
                    m, [&] { return !m.isMoving(); }, 100000)
                > 0);
        QVERIFY(!m.isHoming());
        QVERIFY(m.isHomed());
        QCOMPARE(m.position(), 100);
        // aborted by stop
        QVERIFY(m.startHoming(-5000, 50000));
        QVERIFY(!m.isHomed());
        m.advanceTo(m.time() + 0.05);
        m.stop();
        QVERIFY(!m.isHoming());
        m.advanceTo(m.time() + 1.0);
        QVERIFY(!m.isHomed());
    }

    void deterministicWhateverTheCallPattern()
    {
        // Same seed, same command times, different advanceTo() granularity: identical.
        MotorModel::Config c;
        c.seed = 42;
        MotorModel a(c), b(c);
        QVERIFY(a.enable() && b.enable());
        a.advanceTo(0.5);
        for (int i = 0; i < 500; ++i)
            b.advanceTo(0.0013 + i * 0.001);
        b.advanceTo(0.5);
        QCOMPARE(a.time(), b.time());
        QVERIFY(a.runSpeed(123456) && b.runSpeed(123456));
        a.advanceTo(1.2345);
        for (double t = 0.5; t < 1.2345; t += 0.0173)
            b.advanceTo(t);
        b.advanceTo(1.2345);
        QCOMPARE(a.position(), b.position());
        QCOMPARE(a.speed(), b.speed());
        QCOMPARE(a.current(), b.current());
        QCOMPARE(a.busVoltage(), b.busVoltage());
        QCOMPARE(a.positionError(), b.positionError());
        QCOMPARE(a.temperature(), b.temperature());

        // Another seed: other noise, same mechanics.
        c.seed = 43;
        MotorModel other(c);
        QVERIFY(other.enable());
        other.advanceTo(0.5);
        QVERIFY(other.runSpeed(123456));
        other.advanceTo(1.2345);
        QCOMPARE(other.position(), a.position());
        QVERIFY(other.current() != a.current());
        QVERIFY(other.busVoltage() != a.busVoltage());
    }

    void idleGapMatchesStepping()
    {
        MotorModel::Config c;
        c.loadTorque = 1.0;
        MotorModel a(c), b(c);
        QVERIFY(a.enable() && b.enable());
        a.advanceTo(300.0); // skipped in closed form
        for (int i = 1; i <= 300000; ++i)
            b.advanceTo(i * Dt);
        QCOMPARE(a.time(), b.time());
        QVERIFY(std::abs(a.temperature() - b.temperature()) < 1e-9);
        QCOMPARE(a.current(), b.current());
    }
};

QTEST_APPLESS_MAIN(TestMotorModel)
#include "tst_motormodel.moc"
