#pragma once

#include "sim/motor/servoloop.h"

#include <QtGlobal>

namespace dd {

// The mechanics and electrics behind one simulated drive: a servo (or closed-loop stepper)
// axis with a speed loop, a position profile generator, friction, load, a DC bus and a
// winding temperature. Plain C++, no Qt objects, no clock of its own.
//
// Time. The model is integrated lazily in fixed 1 ms substeps: call advanceTo(seconds) with
// the simulator's clock before reading values or issuing a command; a command takes effect
// at the model's current time (the last whole millisecond reached). Because the substep is
// fixed and the noise is a pure function of (seed, substep, channel), the results depend
// only on the command times quantised to 1 ms, not on how often advanceTo() is called.
// (While the axis is at rest a gap is skipped in closed form; the result then equals the
// step-by-step one up to floating-point rounding.)
//
// Units. Position is in counts (the drive decides what a count is: encoder counts, pulses);
// speed in counts/s, acceleration in counts/s². Config::countsPerRev links them to shaft
// revolutions for torque (N·m), current (A), bus voltage (V) and temperature (°C).
//
// Commands return false and change nothing while the drive is disabled or alarmed; a drive
// whose protocol says "this command enables the servo" calls enable() first.
//
// Closed loop (Config::closedLoop, what the simulated drives use). The profile above is
// then the *reference*: a ServoLoop (position P, speed PI, torque lag, optionally a
// compliant second inertia) makes the shaft follow it in 0.1 ms substeps, and position(),
// speed(), torque, current and the following error are the shaft's. The gains are the
// simulator's own model (docs/tuning.md). When the reference rests and the shaft has
// settled within 0.05 count it is snapped onto it, so that moves still end exactly on their
// target and rest costs nothing. Without closedLoop the shaft is the profile itself, with
// a following error proportional to speed and acceleration.
class MotorModel
{
public:
    struct Config
    {
        double countsPerRev = 10000.0;      // counts per motor revolution
        double maxSpeed = 500000.0;         // counts/s (3000 r/min at 10000 counts/rev)
        double acceleration = 1000000.0;    // counts/s², limit when |speed| grows
        double deceleration = 1000000.0;    // counts/s², limit when |speed| shrinks
        double inertia = 2.0e-4;            // kg·m², rotor + reflected load
        double torqueConstant = 0.5;        // N·m/A
        double ratedTorque = 1.27;          // N·m, 100 % for torquePercent()
        double loadTorque = 0.1;            // N·m the motor supplies while enabled (signed)
        double viscousFriction = 1.0e-4;    // N·m per rad/s
        double coulombFriction = 0.05;      // N·m, opposes motion
        double errorPerSpeed = 2.0e-4;      // following error, counts per count/s
        double errorPerAccel = 5.0e-5;      // following error, counts per count/s²
        double busVoltageNominal = 310.0;   // V
        double busRipple = 1.5;             // V amplitude of the rectifier ripple
        double busRippleHz = 100.0;         // Hz (twice a 50 Hz mains)
        double busSagPerAmp = 0.8;          // V lost per A of motor current
        double windingResistance = 2.0;     // Ω, copper loss I²R heats the motor
        double thermalResistance = 3.0;     // K/W, steady-state rise per watt
        double thermalTimeConstant = 120.0; // s
        double ambientTemperature = 25.0;   // °C
        double currentNoise = 0.02;         // A, uniform ± on the current (and torque) reading
        double voltageNoise = 0.3;          // V, uniform ± on the bus voltage
        double positionErrorNoise = 0.6;    // counts, uniform ± on the following error when enabled
        quint64 seed = 1;                   // noise seed
        // --- the closed loop (closedLoop = true) ---
        bool closedLoop = false;
        ServoLoop::Gains gains;
        double peakTorque = 3.8;          // N·m, torque limit of the loop
        double torqueLagSeconds = 5.0e-4; // current-loop time constant
        double loadInertia = 0.0;         // kg·m², second inertia on a compliant coupling
        double resonanceHz = 0.0;         // > 0 with loadInertia > 0: the coupling's resonance
        double disturbanceTorque = 0.0;   // N·m, uniform ± noise torque (excites a resonance)
    };

    enum class Mode {
        Idle,     // enabled: holding position; disabled: coasting
        Speed,    // speed loop toward targetSpeed()
        Position, // trapezoidal move toward targetPosition()
        Stopping  // decelerating to rest, then Idle
    };

    static constexpr double StepSeconds = 0.001;

    MotorModel();
    explicit MotorModel(const Config &config);

    // --- time ---------------------------------------------------------------------------
    // Integrates up to `seconds` (whole milliseconds; earlier times are ignored). Costs one
    // substep per elapsed millisecond while the axis moves, nothing extra at rest.
    void advanceTo(double seconds);
    double time() const { return static_cast<double>(m_step) * StepSeconds; }

    // --- configuration (takes effect at the current time) ---------------------------------
    // Out-of-range values are sanitised: accelerations >= 1 count/s², inertia > 0, ...
    const Config &config() const { return m_config; }
    void setConfig(const Config &config);
    void setMaxSpeed(double countsPerSecond);
    void setAcceleration(double countsPerSecond2);
    void setDeceleration(double countsPerSecond2);
    void setLoadTorque(double newtonMetres);
    void setGains(const ServoLoop::Gains &gains); // closed loop: takes effect at once
    const ServoLoop::Gains &gains() const { return m_loop.gains(); }
    // The simulated drives' closed loop, with a compliant load resonating at `resonanceHz`
    // (0: rigid) and a disturbance torque on it that keeps exciting the resonance.
    static Config closedLoopConfig(Config config, double resonanceHz = 0.0);
    bool isClosedLoop() const { return m_config.closedLoop; }

    // --- commands -----------------------------------------------------------------------
    bool enable();  // false while alarmed; a coasting shaft is braked to rest
    void disable(); // no torque: the shaft coasts to rest with friction
    // Speed loop toward `countsPerSecond` (clamped to ±maxSpeed) with the accel/decel limits.
    bool runSpeed(double countsPerSecond);
    // Trapezoidal moves at up to `speed` counts/s; they end exactly on the target (integer
    // counts) with zero speed. A relative move is relative to the current (rounded) position; closed
    // loop: to the commanded one (referencePosition), where the shaft settles.
    bool moveAbsolute(qint64 target, double speed);
    bool moveRelative(qint64 delta, double speed);
    // Changes the cruise speed of a move in progress (and of later homing / moves).
    void setMoveSpeed(double speed);
    void stop();          // decelerate to rest at the deceleration limit, stay enabled
    void emergencyStop(); // speed 0 at once, stay enabled (no torque spike is modelled)
    // Homing helper: absolute move to `switchPosition` (where the drive's logic says the
    // origin / limit switch is) at `speed`; on arrival the position is redefined as
    // `homePosition` and isHomed() becomes true. stop(), disable() or an alarm abort it.
    bool startHoming(qint64 switchPosition, double speed, qint64 homePosition = 0);
    // Redefines the current position (the target of a move in progress shifts with it).
    void setPosition(qint64 counts);
    // Alarm: a non-zero code disables the drive (the shaft coasts to rest); clearAlarm()
    // resets the code, the drive stays disabled until enable().
    void injectAlarm(int code);
    void clearAlarm();

    // --- state ----------------------------------------------------------------------------
    Mode mode() const { return m_mode; }
    bool isEnabled() const { return m_enabled; }
    int alarmCode() const { return m_alarm; }
    bool isMoving() const; // shaft turning or a motion command active
    bool isHoming() const { return m_homing; }
    bool isHomed() const { return m_homed; }

    qint64 position() const; // counts (rounded)
    double positionExact() const { return loopActive() ? m_loop.position() : m_pos; }
    qint64 targetPosition() const;  // target of the last move (counts)
    qint64 positionError() const;   // following error, counts (grows with speed and acceleration)
    qint64 commandPosition() const; // position + following error
    double speed() const { return loopActive() ? m_loop.speed() : m_speed; } // counts/s, signed
    double speedRpm() const;                                                 // r/min, signed
    double targetSpeed() const; // where the speed loop is heading now (counts/s)
    double acceleration() const { return loopActive() ? m_loop.acceleration() : m_accel; } // counts/s²
    double referencePosition() const { return m_pos; } // closed loop: where the profile is
    double moveSpeed() const { return m_moveSpeed; }

    double torque() const;                               // N·m, signed (torqueConstant × current)
    double torquePercent() const;                        // % of ratedTorque, signed
    double current() const { return m_current; }         // A, signed
    double busVoltage() const { return m_busVoltage; }   // V
    double temperature() const { return m_temperature; } // °C

    // Deterministic noise in [-1, 1) at the current substep, for the drive's own readouts.
    // Channels 0..15 are used by the model; drives use 16 and above.
    double noiseSample(int channel) const;

private:
    bool loopActive() const { return m_config.closedLoop && m_enabled; }
    void configureLoop();
    void stepLoop(double pos0, double v0);
    bool atRest() const;
    void step();
    void fastForwardIdle(qint64 steps);
    double rampToward(double v, double target) const;
    double positionStep(double v0, bool *finished);
    void updateOutputs();
    void heat(double seconds);
    void finishMove();
    double noiseAt(qint64 step, int channel) const;

    Config m_config;
    qint64 m_step = 0;
    Mode m_mode = Mode::Idle;
    bool m_enabled = false;
    int m_alarm = 0;
    bool m_homing = false;
    bool m_homed = false;
    qint64 m_homePosition = 0;

    double m_pos = 0.0;   // counts
    double m_speed = 0.0; // counts/s
    double m_accel = 0.0; // counts/s²
    double m_targetSpeed = 0.0;
    double m_targetPos = 0.0;
    double m_moveSpeed = 0.0;

    double m_current = 0.0;
    double m_cleanCurrent = 0.0;
    double m_busVoltage = 0.0;
    double m_temperature = 0.0;
    double m_posError = 0.0;

    ServoLoop m_loop;
    bool m_quickStop = false;       // closed loop: braking the speed, the position loop off
    bool m_speedControlled = false; // closed loop: the last substeps ran the speed loop alone
};

} // namespace dd
