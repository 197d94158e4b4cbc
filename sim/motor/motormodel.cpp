#include "sim/motor/motormodel.h"
#include "core/common/mathconstants.h"

#include <algorithm>
#include <cmath>

namespace dd {

namespace {
constexpr double ModelDt = MotorModel::StepSeconds;

// Noise channels used by the model itself.
enum NoiseChannel { CurrentNoise = 0, VoltageNoise = 1, ErrorNoise = 2, DisturbanceNoise = 3 };
constexpr int LoopSubsteps = 10; // ServoLoop substeps per model step (0.1 ms)

// Keeps the integration well defined whatever a drive configures.
MotorModel::Config sanitized(MotorModel::Config c)
{
    c.countsPerRev = c.countsPerRev > 0.0 ? c.countsPerRev : 10000.0;
    c.maxSpeed = std::abs(c.maxSpeed);
    c.acceleration = std::max(std::abs(c.acceleration), 1.0);
    c.deceleration = std::max(std::abs(c.deceleration), 1.0);
    c.inertia = std::max(c.inertia, 1e-9);
    c.thermalTimeConstant = std::max(c.thermalTimeConstant, ModelDt);
    return c;
}

double sgn(double v)
{
    return v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : 0.0);
}

quint64 splitMix64(quint64 x)
{
    x += 0x9E3779B97F4A7C15ULL;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
    return x ^ (x >> 31);
}
} // namespace

MotorModel::MotorModel()
    : MotorModel(Config{})
{
}

MotorModel::MotorModel(const Config &config)
    : m_config(sanitized(config))
{
    m_temperature = m_config.ambientTemperature;
    configureLoop();
    updateOutputs();
}

void MotorModel::configureLoop()
{
    ServoLoop::Plant p;
    p.countsPerRev = m_config.countsPerRev;
    p.inertia = m_config.inertia;
    p.viscousFriction = m_config.viscousFriction;
    p.coulombFriction = m_config.coulombFriction;
    p.loadTorque = m_config.loadTorque;
    p.peakTorque = m_config.peakTorque;
    p.torqueLagSeconds = m_config.torqueLagSeconds;
    p.loadInertia = m_config.loadInertia;
    p.resonanceHz = m_config.resonanceHz;
    p.disturbance = m_config.disturbanceTorque;
    m_loop.configure(p, m_config.gains);
}

bool MotorModel::atRest() const
{
    if (m_speed != 0.0 || m_mode != Mode::Idle)
        return false;
    return !loopActive() || (!m_quickStop && m_loop.isSettled(m_pos));
}

// --- time ---------------------------------------------------------------------------------

void MotorModel::advanceTo(double seconds)
{
    if (!std::isfinite(seconds))
        return;
    const qint64 target = static_cast<qint64>(std::floor(seconds / ModelDt + 1e-6));
    if (target <= m_step)
        return;
    qint64 remaining = target - m_step;
    if (atRest() && remaining > 1) {
        fastForwardIdle(remaining - 1);
        remaining = 1;
    }
    while (remaining-- > 0)
        step();
}

void MotorModel::fastForwardIdle(qint64 steps)
{
    // At rest nothing but the temperature evolves, and the per-step update below is an exact
    // exponential: n steps collapse into one.
    m_accel = 0.0;
    updateOutputs(); // the holding current (no acceleration term any more)
    heat(static_cast<double>(steps) * ModelDt);
    m_step += steps;
}

void MotorModel::step()
{
    const double p0 = m_pos;
    const double v0 = m_speed;
    double v1 = v0;
    bool finished = false;

    if (!m_enabled) {
        // Coasting: friction (and the load, taken as passive) brake the shaft.
        const double toCounts = m_config.countsPerRev / (2.0 * Pi);
        const double omega = std::abs(v0) / toCounts;
        const double brakeTorque = m_config.coulombFriction + std::abs(m_config.loadTorque)
            + m_config.viscousFriction * omega;
        const double dv = brakeTorque / m_config.inertia * toCounts * ModelDt;
        v1 = std::abs(v0) <= dv ? 0.0 : v0 - sgn(v0) * dv;
    } else {
        switch (m_mode) {
        case Mode::Idle: v1 = 0.0; break;
        case Mode::Speed: v1 = rampToward(v0, m_targetSpeed); break;
        case Mode::Stopping:
            v1 = rampToward(v0, 0.0);
            if (v1 == 0.0)
                m_mode = Mode::Idle;
            break;
        case Mode::Position: v1 = positionStep(v0, &finished); break;
        }
    }

    ++m_step;
    if (finished) {
        m_pos = m_targetPos;
        m_speed = 0.0;
        m_accel = -v0 / ModelDt;
        finishMove();
    } else {
        m_pos += 0.5 * (v0 + v1) * ModelDt;
        m_speed = v1;
        m_accel = (v1 - v0) / ModelDt;
    }
    if (loopActive())
        stepLoop(p0, v0);
    updateOutputs();
    heat(ModelDt);
}

// The shaft follows the reference the profile just moved through (linear in between).
void MotorModel::stepLoop(double pos0, double v0)
{
    // Speed mode and the stop after it run the speed loop alone (as a drive in speed
    // control does); moves and holding run the position loop around it.
    const bool speedControl = m_quickStop || m_mode == Mode::Speed || m_mode == Mode::Stopping;
    if (!speedControl && m_speedControlled) {
        // Speed control just ended: hold the whole count the shaft is at, as a drive does.
        m_pos = std::round(m_loop.position());
        m_targetPos = m_pos;
        pos0 = m_pos;
    }
    m_speedControlled = speedControl;
    const double accel = (m_speed - v0) / ModelDt;
    for (int i = 1; i <= LoopSubsteps; ++i) {
        const double f = double(i) / LoopSubsteps;
        const double noise = noiseAt((m_step - 1) * LoopSubsteps + i, DisturbanceNoise);
        if (speedControl)
            m_loop.step(m_loop.position(), m_quickStop ? 0.0 : v0 + (m_speed - v0) * f, noise, false,
                        m_quickStop ? 0.0 : accel);
        else
            m_loop.step(pos0 + (m_pos - pos0) * f, v0 + (m_speed - v0) * f, noise, true, accel);
    }
    if (speedControl && !m_quickStop) {
        // Speed control: the position reference is wherever the shaft is.
        m_pos = m_loop.position();
    } else if (m_quickStop) {
        // Braked without the position loop; where the shaft comes to rest it stays.
        m_pos = m_loop.position();
        m_targetPos = m_pos;
        if (std::abs(m_loop.speed()) * 60.0 < m_config.countsPerRev) { // below 1 r/min: hold here
            m_quickStop = false;
            m_speedControlled = false;
            m_pos = m_targetPos = std::round(m_loop.position());
        }
    } else if (m_speed == 0.0 && m_mode == Mode::Idle && m_loop.isSettled(m_pos)) {
        m_loop.settleAt(m_pos);
    }
}

double MotorModel::rampToward(double v, double target) const
{
    if (v == target)
        return v;
    const bool shrinking = v != 0.0 && (target == 0.0 || (v > 0.0) != (target > 0.0) || std::abs(target) < std::abs(v));
    if (shrinking) {
        const double goal = (target != 0.0 && (v > 0.0) == (target > 0.0)) ? target : 0.0;
        const double dv = m_config.deceleration * ModelDt;
        return std::abs(v - goal) <= dv ? goal : v - sgn(v) * dv;
    }
    const double dv = m_config.acceleration * ModelDt;
    return std::abs(target - v) <= dv ? target : v + sgn(target - v) * dv;
}

// One substep of the trapezoidal move. The speed is kept at or below the braking curve
// v² = 2·d·r (r = distance left) using the trapezoidal position update, so that the axis
// arrives with zero speed; the last step snaps onto the integer target (the snap is
// shorter than half a substep's travel at a speed below d·dt).
double MotorModel::positionStep(double v0, bool *finished)
{
    const double r = m_targetPos - m_pos;
    const double dir = sgn(r);
    const double a = m_config.acceleration;
    const double d = m_config.deceleration;
    const double vAbs = std::abs(v0);

    if (v0 != 0.0 && sgn(v0) != dir) {
        // Moving away from the target (overshoot after a target or limit change): brake.
        const double dv = d * ModelDt;
        if (dir == 0.0 && vAbs <= dv) {
            *finished = true;
            return 0.0;
        }
        return vAbs <= dv ? 0.0 : v0 - sgn(v0) * dv;
    }

    const double rAbs = std::abs(r);
    if (rAbs == 0.0) {
        *finished = true;
        return 0.0;
    }
    if (vAbs <= d * ModelDt && 0.5 * vAbs * ModelDt >= rAbs) {
        *finished = true; // stopping within this step reaches the target
        return 0.0;
    }

    const double vMax = std::min(m_moveSpeed, m_config.maxSpeed);
    const double inner = d * d * ModelDt * ModelDt + 4.0 * (2.0 * d * rAbs - d * ModelDt * vAbs);
    const double brake = inner > 0.0 ? 0.5 * (-d * ModelDt + std::sqrt(inner)) : 0.0;
    double vNew = std::min({vAbs + a * ModelDt, vMax, brake});
    vNew = std::max({vNew, vAbs - d * ModelDt, 0.0});
    return dir * vNew;
}

void MotorModel::finishMove()
{
    m_mode = Mode::Idle;
    if (m_homing) {
        m_homing = false;
        m_homed = true;
        const double shift = static_cast<double>(m_homePosition) - m_pos;
        m_pos += shift;
        m_targetPos += shift;
        if (loopActive())
            m_loop.shift(shift);
    }
}

void MotorModel::updateOutputs()
{
    const double v1 = m_speed;
    const double toRad = 2.0 * Pi / m_config.countsPerRev;
    const double t = time();

    if (loopActive()) {
        m_cleanCurrent = m_config.torqueConstant > 0.0 ? m_loop.torque() / m_config.torqueConstant : 0.0;
        m_current = m_cleanCurrent + m_config.currentNoise * noiseAt(m_step, CurrentNoise);
        m_posError = m_pos - m_loop.position();
    } else if (m_enabled) {
        const double omega = v1 * toRad;
        const double alpha = m_accel * toRad;
        const double torque = m_config.inertia * alpha + m_config.loadTorque + m_config.viscousFriction * omega
            + m_config.coulombFriction * sgn(v1);
        m_cleanCurrent = m_config.torqueConstant > 0.0 ? torque / m_config.torqueConstant : 0.0;
        m_current = m_cleanCurrent + m_config.currentNoise * noiseAt(m_step, CurrentNoise);
        m_posError = m_config.errorPerSpeed * v1 + m_config.errorPerAccel * m_accel
            + m_config.positionErrorNoise * noiseAt(m_step, ErrorNoise);
    } else {
        m_cleanCurrent = 0.0;
        m_current = 0.0;
        m_posError = 0.0;
    }

    m_busVoltage = m_config.busVoltageNominal - m_config.busSagPerAmp * std::abs(m_cleanCurrent)
        + m_config.busRipple * std::sin(2.0 * Pi * m_config.busRippleHz * t)
        + m_config.voltageNoise * noiseAt(m_step, VoltageNoise);
}

// First-order thermal model: tau·dT/dt = ambient + P·Rth − T with P = I²·R (noise-free
// current), integrated exactly over `seconds` at constant power.
void MotorModel::heat(double seconds)
{
    const double power = m_cleanCurrent * m_cleanCurrent * m_config.windingResistance;
    const double steady = m_config.ambientTemperature + power * m_config.thermalResistance;
    m_temperature = steady + (m_temperature - steady) * std::exp(-seconds / m_config.thermalTimeConstant);
}

double MotorModel::noiseAt(qint64 step, int channel) const
{
    const quint64 h = splitMix64(m_config.seed
                                 ^ splitMix64(static_cast<quint64>(step) * 64u + static_cast<quint64>(channel)));
    // 53 random bits → [0, 1) → [-1, 1)
    return static_cast<double>(h >> 11) * (1.0 / 9007199254740992.0) * 2.0 - 1.0;
}

double MotorModel::noiseSample(int channel) const
{
    return noiseAt(m_step, channel);
}

// --- configuration ------------------------------------------------------------------------

void MotorModel::setConfig(const Config &config)
{
    const bool wasActive = loopActive();
    m_config = sanitized(config);
    configureLoop();
    if (loopActive() && !wasActive)
        m_loop.engage(m_pos, m_speed);
    updateOutputs();
}

MotorModel::Config MotorModel::closedLoopConfig(Config config, double resonanceHz)
{
    config.closedLoop = true;
    if (resonanceHz > 0.0) {
        config.loadInertia = 0.2 * config.inertia;
        config.resonanceHz = resonanceHz;
        config.disturbanceTorque = 0.05;
    }
    return config;
}

void MotorModel::setGains(const ServoLoop::Gains &gains)
{
    m_loop.setGains(gains);
    m_config.gains = m_loop.gains();
}

void MotorModel::setMaxSpeed(double countsPerSecond)
{
    m_config.maxSpeed = std::abs(countsPerSecond);
    if (m_mode == Mode::Speed)
        m_targetSpeed = std::clamp(m_targetSpeed, -m_config.maxSpeed, m_config.maxSpeed);
}

void MotorModel::setAcceleration(double v)
{
    m_config.acceleration = std::max(std::abs(v), 1.0);
}
void MotorModel::setDeceleration(double v)
{
    m_config.deceleration = std::max(std::abs(v), 1.0);
}
void MotorModel::setLoadTorque(double newtonMetres)
{
    m_config.loadTorque = newtonMetres;
    configureLoop();
}

// --- commands -----------------------------------------------------------------------------

bool MotorModel::enable()
{
    if (m_alarm != 0)
        return false;
    if (!m_enabled) {
        m_enabled = true;
        m_mode = m_speed != 0.0 ? Mode::Stopping : Mode::Idle;
        m_quickStop = false;
        m_speedControlled = false;
        if (loopActive()) {
            m_loop.engage(m_pos, m_speed);
            if (m_speed == 0.0) // hold the nearest whole count (position commands are counts)
                m_pos = m_targetPos = std::round(m_pos);
        }
    }
    return true;
}

void MotorModel::disable()
{
    if (loopActive()) {
        // The shaft coasts on from where the loop left it.
        m_pos = m_loop.position();
        m_speed = m_loop.speed();
        m_quickStop = false;
        m_speedControlled = false;
    }
    m_enabled = false;
    m_mode = Mode::Idle;
    m_homing = false;
    m_targetSpeed = 0.0;
}

bool MotorModel::runSpeed(double countsPerSecond)
{
    if (!m_enabled)
        return false;
    m_homing = false;
    m_targetSpeed = std::clamp(countsPerSecond, -m_config.maxSpeed, m_config.maxSpeed);
    m_mode = Mode::Speed;
    return true;
}

bool MotorModel::moveAbsolute(qint64 target, double speed)
{
    if (!m_enabled)
        return false;
    m_homing = false;
    m_targetPos = static_cast<double>(target);
    m_moveSpeed = std::abs(speed);
    m_mode = Mode::Position;
    return true;
}

bool MotorModel::moveRelative(qint64 delta, double speed)
{
    // Closed loop: from the commanded position, as a servo in position mode adds an increment
    // to its position command; the shaft may still be settling a few counts away from it.
    const qint64 from = loopActive() ? std::llround(m_pos) : position();
    return moveAbsolute(from + delta, speed);
}

void MotorModel::setMoveSpeed(double speed)
{
    m_moveSpeed = std::abs(speed);
}

void MotorModel::stop()
{
    m_homing = false;
    m_targetSpeed = 0.0;
    if (m_enabled)
        m_mode = m_speed != 0.0 ? Mode::Stopping : Mode::Idle;
}

void MotorModel::emergencyStop()
{
    m_homing = false;
    m_targetSpeed = 0.0;
    m_speed = 0.0;
    m_accel = 0.0;
    m_mode = Mode::Idle;
    if (loopActive()) {
        // The reference stops at once; the loop brakes the shaft at its torque limit.
        m_pos = m_loop.position();
        m_quickStop = true;
    }
    updateOutputs();
}

bool MotorModel::startHoming(qint64 switchPosition, double speed, qint64 homePosition)
{
    if (!moveAbsolute(switchPosition, speed))
        return false;
    m_homing = true;
    m_homed = false;
    m_homePosition = homePosition;
    return true;
}

void MotorModel::setPosition(qint64 counts)
{
    const double shift = static_cast<double>(counts) - positionExact();
    m_pos += shift;
    m_targetPos += shift;
    if (loopActive())
        m_loop.shift(shift);
}

void MotorModel::injectAlarm(int code)
{
    if (code == 0)
        return;
    m_alarm = code;
    disable();
}

void MotorModel::clearAlarm()
{
    m_alarm = 0;
}

// --- state --------------------------------------------------------------------------------

bool MotorModel::isMoving() const
{
    if (m_speed != 0.0 || m_mode != Mode::Idle)
        return true;
    // Closed loop: still braking, turning faster than 1 r/min, or not yet within half a count of
    // the reference: in position, the position reads the target
    // (a disturbance at rest trembles the shaft without moving it).
    return loopActive()
        && (m_quickStop || std::abs(m_loop.speed()) * 60.0 > m_config.countsPerRev
            || std::abs(m_loop.position() - m_pos) >= 0.5);
}

qint64 MotorModel::position() const
{
    return std::llround(positionExact());
}
qint64 MotorModel::targetPosition() const
{
    return std::llround(m_targetPos);
}
qint64 MotorModel::positionError() const
{
    return std::llround(m_posError);
}
qint64 MotorModel::commandPosition() const
{
    return loopActive() ? std::llround(m_pos) : std::llround(m_pos + m_posError);
}
double MotorModel::speedRpm() const
{
    return speed() * 60.0 / m_config.countsPerRev;
}

double MotorModel::targetSpeed() const
{
    switch (m_mode) {
    case Mode::Speed: return m_targetSpeed;
    case Mode::Position: return sgn(m_targetPos - m_pos) * std::min(m_moveSpeed, m_config.maxSpeed);
    case Mode::Idle:
    case Mode::Stopping: return 0.0;
    }
    return 0.0;
}

double MotorModel::torque() const
{
    return m_config.torqueConstant * m_current;
}

double MotorModel::torquePercent() const
{
    return m_config.ratedTorque > 0.0 ? 100.0 * torque() / m_config.ratedTorque : 0.0;
}

} // namespace dd
