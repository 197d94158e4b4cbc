#include "sim/motor/motormodel.h"

#include <QtTest>
#include <cmath>
#include <vector>

using namespace dd;

namespace {
constexpr double Pi = 3.14159265358979323846;

MotorModel::Config closedLoop(double speedKpHz, double speedKi = 30.0)
{
    MotorModel::Config c;
    c.closedLoop = true;
    c.gains.speedKpHz = speedKpHz;
    c.gains.speedKi = speedKi;
    c.gains.torqueFeedforward = 0.0; // the speed loop alone (a step would saturate a feed-forward)
    c.acceleration = 1e9;            // a step of the speed reference
    c.deceleration = 1e9;
    c.currentNoise = 0.0;
    return c;
}

// The speed, sampled every millisecond, after a step from rest to `target` counts/s.
std::vector<double> speedStep(MotorModel::Config c, double target, int ms)
{
    MotorModel m(c);
    m.enable();
    m.advanceTo(0.010);
    m.runSpeed(target);
    std::vector<double> v;
    for (int i = 1; i <= ms; ++i) {
        m.advanceTo(0.010 + i * 0.001);
        v.push_back(m.speed());
    }
    return v;
}

struct StepFigures
{
    double riseTime = 0.0;  // s, 10 → 90 %
    double overshoot = 0.0; // %
    int crossings = 0;      // of the final value after the first arrival (ringing)
};

StepFigures figures(const std::vector<double> &v, double target, double dt)
{
    StepFigures f;
    int t10 = -1, t90 = -1;
    double peak = 0.0;
    for (int i = 0; i < int(v.size()); ++i) {
        if (t10 < 0 && v[i] >= 0.1 * target)
            t10 = i;
        if (t90 < 0 && v[i] >= 0.9 * target)
            t90 = i;
        peak = std::max(peak, v[i]);
    }
    f.riseTime = (t90 - t10) * dt;
    f.overshoot = 100.0 * (peak - target) / target;
    bool above = false;
    for (int i = std::max(t90, 0); i < int(v.size()); ++i) {
        const bool now = v[i] > target;
        if (i > t90 && now != above)
            ++f.crossings;
        above = now;
    }
    return f;
}
} // namespace

// The magnitude of a DFT bin at `hz` of samples taken every `dt` (mean removed).
double dftMagnitude(const std::vector<double> &x, double dt, double hz)
{
    double mean = 0.0;
    for (double v : x)
        mean += v;
    mean /= double(x.size());
    double re = 0.0, im = 0.0;
    for (size_t i = 0; i < x.size(); ++i) {
        const double w = 0.5 - 0.5 * std::cos(2.0 * Pi * double(i) / double(x.size() - 1)); // Hann
        re += (x[i] - mean) * w * std::cos(2.0 * Pi * hz * double(i) * dt);
        im -= (x[i] - mean) * w * std::sin(2.0 * Pi * hz * double(i) * dt);
    }
    return std::hypot(re, im);
}

class TestServoLoop : public QObject
{
    Q_OBJECT

private slots:
    void raisingSpeedGainShortensRiseAndRaisesOvershoot()
    {
        const double target = 30000.0; // 180 r/min: the torque stays below its limit
        const StepFigures soft = figures(speedStep(closedLoop(30.0), target, 300), target, 0.001);
        const StepFigures stiff = figures(speedStep(closedLoop(60.0), target, 300), target, 0.001);
        qInfo("speed-kp 30 Hz: rise %.1f ms, overshoot %.1f %%; 60 Hz: rise %.1f ms, overshoot %.1f %%",
              soft.riseTime * 1e3, soft.overshoot, stiff.riseTime * 1e3, stiff.overshoot);
        QVERIFY(stiff.riseTime < soft.riseTime);
        QVERIFY(stiff.overshoot > soft.overshoot + 5.0);
        QVERIFY(soft.crossings <= 2); // a well damped loop crosses its final value once or twice
    }

    void tooHighGainRings()
    {
        const double target = 30000.0;
        const std::vector<double> v = speedStep(closedLoop(100.0), target, 300);
        const StepFigures f = figures(v, target, 0.001);
        QVERIFY2(f.crossings >= 5, qPrintable(QString::number(f.crossings)));
        QVERIFY(f.overshoot > 40.0);
        // ...but it still converges (bounded by the torque limit): the final value is reached.
        QVERIFY(std::abs(v.back() - target) < 0.02 * target);
    }

    void moveEndsExactlyOnTargetThroughTheLoop()
    {
        MotorModel::Config c;
        c.closedLoop = true;
        MotorModel m(c);
        QVERIFY(m.enable());
        QVERIFY(m.moveAbsolute(25000, 100000));
        qint64 peakError = 0;
        double t = 0.0;
        while (m.isMoving() && t < 2.0) {
            t += 0.001;
            m.advanceTo(t);
            peakError = std::max(peakError, std::abs(m.positionError()));
        }
        QVERIFY2(!m.isMoving(), "the loop did not settle");
        QCOMPARE(m.position(), 25000);         // in position: within half a count
        QVERIFY(std::abs(m.speedRpm()) < 1.0); // and slower than 1 r/min
        m.advanceTo(t + 0.5);
        QCOMPARE(m.positionExact(), 25000.0); // settled: snapped onto the target
        QCOMPARE(m.speed(), 0.0);
        QVERIFY(peakError > 0); // the shaft lags its reference while it accelerates
        QVERIFY(peakError < 2000);
        // Holding costs nothing: a long rest is skipped and stays on target.
        m.advanceTo(t + 100.0);
        QCOMPARE(m.position(), 25000);
        QVERIFY(std::abs(m.current() - c.loadTorque / c.torqueConstant) < 3 * c.currentNoise + 1e-9);
    }

    void loadTorqueHeldWithoutSteadyStateError()
    {
        MotorModel::Config c = closedLoop(30.0);
        c.loadTorque = 0.8;
        MotorModel m(c);
        QVERIFY(m.enable());
        QVERIFY(m.runSpeed(20000));
        m.advanceTo(0.5);
        QVERIFY2(std::abs(m.speed() - 20000) < 20, qPrintable(QString::number(m.speed())));
        QVERIFY(m.current() > c.loadTorque / c.torqueConstant); // load plus friction
    }

    void emergencyStopBrakesAndStays()
    {
        MotorModel m(closedLoop(30.0));
        QVERIFY(m.enable());
        QVERIFY(m.runSpeed(200000));
        m.advanceTo(0.2);
        m.emergencyStop();
        double t = 0.2;
        while (m.isMoving() && t < 1.0) {
            t += 0.001;
            m.advanceTo(t);
        }
        QVERIFY(!m.isMoving());
        const qint64 at = m.position();
        m.advanceTo(t + 1.0);
        QVERIFY(std::abs(m.position() - at) <= 1);
        QVERIFY(std::abs(m.torque()) <= c_peak());
    }

    void resonancePeakAtTheChosenFrequency()
    {
        MotorModel::Config c = closedLoop(30.0);
        c.loadInertia = 0.2 * c.inertia;
        c.resonanceHz = 80.0;
        c.disturbanceTorque = 0.05;
        MotorModel m(c);
        QVERIFY(m.enable());
        std::vector<double> v;
        for (int i = 1; i <= 2000; ++i) { // 2 s at rest, 1 kHz
            m.advanceTo(i * 0.001);
            v.push_back(m.speed());
        }
        double bestHz = 0.0, best = 0.0;
        for (double hz = 20.0; hz <= 400.0; hz += 0.5) {
            const double mag = dftMagnitude(v, 0.001, hz);
            if (mag > best) {
                best = mag;
                bestHz = hz;
            }
        }
        qInfo("resonance 80 Hz: speed spectrum peak at %.1f Hz", bestHz);
        QVERIFY2(std::abs(bestHz - 80.0) <= 8.0, qPrintable(QString::number(bestHz)));
        QVERIFY(m.isEnabled()); // the disturbance trembles the shaft but does not move it away
        QVERIFY(!m.isMoving());
    }

private:
    static double c_peak() { return MotorModel::Config{}.peakTorque; }
};

QTEST_GUILESS_MAIN(TestServoLoop)
#include "tst_servoloop.moc"
