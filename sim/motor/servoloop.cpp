#include "sim/motor/servoloop.h"
#include "core/common/mathconstants.h"

#include <algorithm>
#include <cmath>

namespace dd {

namespace {
constexpr double LoopDt = ServoLoop::StepSeconds;
constexpr double ControlDt = LoopDt * ServoLoop::ControlDivider;
constexpr double FrictionSmoothing = 2.0; // rad/s: Coulomb friction is tanh(ω / this)
} // namespace

void ServoLoop::configure(const Plant &plant, const Gains &gains)
{
    m_plant = plant;
    m_plant.inertia = std::max(m_plant.inertia, 1e-9);
    m_plant.loadInertia = std::max(m_plant.loadInertia, 0.0);
    m_plant.peakTorque = std::max(std::abs(m_plant.peakTorque), 1e-6);
    m_plant.torqueLagSeconds = std::max(m_plant.torqueLagSeconds, 0.0);
    m_plant.speedFilterSeconds = std::max(m_plant.speedFilterSeconds, 0.0);
    m_filterDecay = m_plant.speedFilterSeconds > 0.0 ? std::exp(-ControlDt / m_plant.speedFilterSeconds) : 0.0;
    m_countsPerRad = (m_plant.countsPerRev > 0.0 ? m_plant.countsPerRev : 10000.0) / (2.0 * Pi);
    m_stiffness = 0.0;
    m_damping = 0.0;
    if (m_plant.loadInertia > 0.0 && m_plant.resonanceHz > 0.0) {
        // Two masses on a spring: ω_r² = k (1/J1 + 1/J2).
        const double w = 2.0 * Pi * m_plant.resonanceHz;
        const double reduced = 1.0 / (1.0 / m_plant.inertia + 1.0 / m_plant.loadInertia);
        m_stiffness = w * w * reduced;
        m_damping = 2.0 * m_plant.dampingRatio * std::sqrt(m_stiffness * reduced);
    }
    setGains(gains);
}

void ServoLoop::setGains(const Gains &gains)
{
    m_gains.speedKpHz = std::clamp(gains.speedKpHz, 0.0, 5000.0);
    m_gains.speedKi = std::clamp(gains.speedKi, 0.0, 100000.0);
    m_gains.positionKp = std::clamp(gains.positionKp, 0.0, 5000.0);
    m_gains.feedforward = std::clamp(gains.feedforward, 0.0, 1.0);
    m_gains.torqueFeedforward = std::clamp(gains.torqueFeedforward, 0.0, 1.0);
}

void ServoLoop::engage(double position, double speed)
{
    m_pos1 = m_pos2 = position / m_countsPerRad;
    m_vel1 = m_vel2 = speed / m_countsPerRad;
    m_acc1 = 0.0;
    m_lastControlPos = m_pos1 - m_vel1 * ControlDt;
    m_filteredSpeed = m_filteredCommand = m_vel1;
    m_substep = 0;
    const double kp = estimatedInertia() * 2.0 * Pi * m_gains.speedKpHz;
    const double hold = m_plant.loadTorque + m_plant.viscousFriction * m_vel1
        + m_plant.coulombFriction * std::tanh(m_vel1 / FrictionSmoothing);
    m_integral = kp > 0.0 && m_gains.speedKi > 0.0 ? hold / (kp * m_gains.speedKi) : 0.0;
    m_command = m_applied = m_torque = std::clamp(hold, -m_plant.peakTorque, m_plant.peakTorque);
}

void ServoLoop::control(double refPosition, double refSpeed, bool positionLoop, double refAcceleration)
{
    // The command computed last period takes effect now (computation delay).
    m_applied = m_command;

    const double raw = (m_pos1 - m_lastControlPos) / ControlDt; // encoder speed
    m_lastControlPos = m_pos1;
    m_filteredSpeed += (raw - m_filteredSpeed) * (1.0 - m_filterDecay);
    const double measured = m_filteredSpeed;
    double speedCommand = refSpeed / m_countsPerRad;
    if (positionLoop)
        speedCommand = m_gains.feedforward * speedCommand
            + m_gains.positionKp * (refPosition / m_countsPerRad - m_pos1);
    // The command passes the same filter as the measurement: with the feed-forward the
    // shaft follows a ramp without the error (and the integrator) seeing the filter's lag.
    m_filteredCommand += (speedCommand - m_filteredCommand) * (1.0 - m_filterDecay);
    const double error = m_filteredCommand - measured;
    const double kp = estimatedInertia() * 2.0 * Pi * m_gains.speedKpHz;
    const double integral = m_integral + error * ControlDt;
    const double feedforward = m_gains.torqueFeedforward * estimatedInertia() * refAcceleration / m_countsPerRad;
    const double unclamped = kp * (error + m_gains.speedKi * integral) + feedforward;
    m_command = std::clamp(unclamped, -m_plant.peakTorque, m_plant.peakTorque);
    // Anti-windup: integrate only while the command is not saturated (or the error unwinds it).
    if (std::abs(unclamped) <= m_plant.peakTorque || (unclamped > m_command) != (error > 0.0))
        m_integral = integral;
}

void ServoLoop::step(double refPosition, double refSpeed, double noise, bool positionLoop, double refAcceleration)
{
    if (m_substep % ControlDivider == 0)
        control(refPosition, refSpeed, positionLoop, refAcceleration);
    ++m_substep;

    if (m_plant.torqueLagSeconds > 0.0)
        m_torque += (m_applied - m_torque) * (1.0 - std::exp(-LoopDt / m_plant.torqueLagSeconds));
    else
        m_torque = m_applied;

    const double friction = m_plant.viscousFriction * m_vel1
        + m_plant.coulombFriction * std::tanh(m_vel1 / FrictionSmoothing);
    double coupling = 0.0;
    if (m_stiffness > 0.0)
        coupling = m_stiffness * (m_pos1 - m_pos2) + m_damping * (m_vel1 - m_vel2);
    const double disturbance = m_plant.disturbance * noise;

    // Semi-implicit Euler: speeds first, then positions with the new speeds.
    const double inertia1 = m_stiffness > 0.0 ? m_plant.inertia : m_plant.inertia + m_plant.loadInertia;
    // The disturbance acts on the load when there is one (a process torque), else on the shaft.
    m_acc1 = (m_torque - friction - m_plant.loadTorque - coupling + (m_stiffness > 0.0 ? 0.0 : disturbance)) / inertia1;
    m_vel1 += m_acc1 * LoopDt;
    m_pos1 += m_vel1 * LoopDt;
    if (m_stiffness > 0.0) {
        m_vel2 += (coupling + disturbance) / m_plant.loadInertia * LoopDt;
        m_pos2 += m_vel2 * LoopDt;
    } else {
        m_vel2 = m_vel1;
        m_pos2 = m_pos1;
    }
}

void ServoLoop::shift(double counts)
{
    const double r = counts / m_countsPerRad;
    m_pos1 += r;
    m_pos2 += r;
    m_lastControlPos += r;
}

bool ServoLoop::isSettled(double refPosition) const
{
    if (m_plant.disturbance != 0.0)
        return false;
    const double restSpeed = 0.5 / m_countsPerRad; // half a count per second
    return std::abs(m_pos1 * m_countsPerRad - refPosition) < 0.05 && std::abs(m_vel1) < restSpeed
        && std::abs(m_vel2) < restSpeed && std::abs(m_pos2 - m_pos1) * m_countsPerRad < 0.05;
}

void ServoLoop::settleAt(double refPosition)
{
    m_pos1 = m_pos2 = m_lastControlPos = refPosition / m_countsPerRad;
    m_vel1 = m_vel2 = m_acc1 = 0.0;
    m_filteredSpeed = m_filteredCommand = 0.0;
}

} // namespace dd
