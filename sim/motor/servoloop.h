#pragma once

#include <QtGlobal>

namespace dd {

// The simulator's own closed loop: a position loop (P, with speed feed-forward) around a
// speed loop (PI) around a first-order torque (current) loop, driving a mechanical plant
// (motor inertia, viscous and Coulomb friction, a load torque, and optionally a second
// inertia on a compliant coupling: a resonance). It is DriveDesk's invented model for
// rehearsing tuning, not any real drive's control structure (docs/tuning.md).
//
// Units: positions in counts, speeds in counts/s, torques in N·m; internally radians.
// The plant is integrated in fixed StepSeconds substeps; the controller runs every
// ControlDivider substeps and its torque command takes effect one control period later (the
// computation delay of a sampled controller), the speed it sees is the position difference
// over one control period (an encoder's speed), low-pass filtered. Those delays, with the torque loop's lag,
// are what makes a too-high speed gain ring, as on a real drive.
class ServoLoop
{
public:
    struct Gains
    {
        double speedKpHz = 60.0;        // speed-loop gain as a bandwidth: torque = Jest·2π·kp·(e + ki·∫e)
        double speedKi = 60.0;          // speed-loop integral gain, 1/s
        double positionKp = 60.0;       // position-loop gain, 1/s (speed command per count of error)
        double feedforward = 1.0;       // speed feed-forward, 0..1
        double torqueFeedforward = 1.0; // acceleration (torque) feed-forward, 0..1: Jest · reference acceleration
    };
    struct Plant
    {
        double countsPerRev = 10000.0;
        double inertia = 2.0e-4;          // kg·m², motor side
        double viscousFriction = 1e-4;    // N·m per rad/s
        double coulombFriction = 0.05;    // N·m (smoothed near standstill)
        double loadTorque = 0.1;          // N·m, signed, acting against positive torque
        double peakTorque = 3.8;          // N·m, the torque command saturates here
        double torqueLagSeconds = 5e-4;   // time constant of the torque (current) loop
        double speedFilterSeconds = 1e-3; // low-pass on the measured speed
        double loadInertia = 0.0;         // kg·m² on the coupling; 0: rigid (no second mass)
        double resonanceHz = 0.0;         // free-free resonance of the two masses
        double dampingRatio = 0.02;       // of the coupling
        double disturbance = 0.0;         // N·m, uniform ± torque noise (excites the resonance)
    };

    static constexpr double StepSeconds = 1.0e-4;
    static constexpr int ControlDivider = 5; // the controller runs at 2 kHz

    void configure(const Plant &plant, const Gains &gains);
    void setGains(const Gains &gains);
    const Gains &gains() const { return m_gains; }
    const Plant &plant() const { return m_plant; }
    bool hasCoupling() const { return m_stiffness > 0.0; }

    // Takes over at this state: motor and load at `position`, both turning at `speed`,
    // the integrator preloaded with the load torque (a drive that was holding).
    void engage(double position, double speed);
    // One substep toward the reference (position, speed). `noise` in [-1, 1) scales the
    // disturbance torque. Without the position loop the speed command is `refSpeed` alone
    // (a quick stop brakes the speed, wherever the axis ends).
    void step(double refPosition, double refSpeed, double noise, bool positionLoop, double refAcceleration = 0.0);
    // Moves every position by `counts` (a redefined origin).
    void shift(double counts);
    // At rest on `refPosition` within a fraction of a count and without disturbance: the
    // caller may then snap onto it (settleAt) and skip time in closed form.
    bool isSettled(double refPosition) const;
    void settleAt(double refPosition);

    double position() const { return m_pos1 * m_countsPerRad; }     // counts
    double speed() const { return m_vel1 * m_countsPerRad; }        // counts/s
    double acceleration() const { return m_acc1 * m_countsPerRad; } // counts/s²
    double loadPosition() const { return m_pos2 * m_countsPerRad; }
    double torque() const { return m_torque; } // N·m the motor produces

private:
    double estimatedInertia() const { return m_plant.inertia + m_plant.loadInertia; }
    void control(double refPosition, double refSpeed, bool positionLoop, double refAcceleration);

    Plant m_plant;
    Gains m_gains;
    double m_countsPerRad = 10000.0 / 6.283185307179586;
    double m_stiffness = 0.0; // N·m/rad
    double m_damping = 0.0;   // N·m·s/rad
    int m_substep = 0;

    double m_pos1 = 0.0, m_vel1 = 0.0, m_acc1 = 0.0; // motor, rad
    double m_pos2 = 0.0, m_vel2 = 0.0;               // load, rad
    double m_lastControlPos = 0.0;
    double m_filteredSpeed = 0.0;   // rad/s
    double m_filteredCommand = 0.0; // rad/s
    double m_filterDecay = 0.0;     // per control period
    double m_integral = 0.0;        // ∫ speed error, rad
    double m_command = 0.0;         // torque command computed, N·m (applies next period)
    double m_applied = 0.0;         // torque command in force
    double m_torque = 0.0;          // torque produced
};

} // namespace dd
