#pragma once

#include "sim/motor/motormodel.h"

#include <QJsonObject>
#include <QtGlobal>

namespace dd {

// The mechanics behind a simulated Shuoke drive: a MotorModel in pulses (pulses/s), the
// left / right limit switches and the origin switch at fixed motor positions, homing, and
// the drive's position counters.
//
// Coordinates. The motor position is physical (where the switches are). The counters the
// protocol reads are offsets from it:
//   0x37 absolute pulse counter, 0x39 relative pulse counter: the commanded position
//        (closed loop: motor position + following error; open loop: motor position);
//   0x58 / 0x5A closed-loop absolute / relative position: the encoder (motor position).
// Clearing a counter (0x38, 0x3A, 0x59/0x5B without data) moves its offset; homing zeroes
// all four at the origin switch.
//
// Limits. Motion toward an active limit switch stops at once (emergency stop); motion away
// from it is allowed.
// Homing (0x3E): run at the homing speed in the first direction; at the origin switch stop
// and zero the counters; at a limit switch reverse once; at the second limit give up
// (homingFailed()).
// The model is advanced in 1 ms steps while anything moves, so that a switch is never
// jumped over at the speeds the protocol allows (100000 pulses/s = 100 pulses per step;
// the origin test looks for a crossing, not a window).
class SimShuokeAxis
{
public:
    struct Switches
    {
        qint64 leftLimit = -1000000; // motor position at or below which the left limit is active
        qint64 rightLimit = 1000000; // at or above which the right limit is active
        qint64 origin = 0;           // origin switch position
        qint64 originWidth = 20;     // the origin input reads 1 within this distance
    };

    explicit SimShuokeAxis(bool closedLoop = true);

    void advanceTo(qint64 nowUs);
    qint64 nowUs() const { return m_nowUs; }

    const Switches &switches() const { return m_switches; }
    void setSwitches(const Switches &s) { m_switches = s; }
    void setClosedLoop(bool on) { m_closedLoop = on; }
    // The power stage (the drive's ENA input): off, the shaft coasts to rest, a homing run
    // ends and motion commands are ignored; on again, the motor holds its position.
    void setPowered(bool on);
    bool isPowered() const { return m_motor.isEnabled(); }
    void setAcceleration(double pulsesPerSecond2);
    void setDeceleration(double pulsesPerSecond2);

    // Motion commands (signed pulses / pulses/s in the drive's direction).
    void runSpeed(double speed);
    void changeSpeed(double speed); // 0x35: magnitude, keeps the direction
    void moveRelative(qint64 distance, double speed);
    void moveToMotorPosition(qint64 target, double speed);
    void stop();
    void emergencyStop();
    // How a homing run searches (seed 0x3E and the 1-byte forms of 0x4E / 0x4F).
    enum class Homing {
        ReverseAtLimit, // 0x3E: toward the origin, reverse once at a limit, zero the counters
        LimitFirst,     // 0x4E: to the limit first, then back to the origin, zero the counters
        KeepCounters,   // 0x4F: as 0x3E, the counters are not zeroed
    };
    void startHoming(bool positiveFirst, double speed, Homing how = Homing::ReverseAtLimit);

    bool isRunning() const;
    bool isHoming() const { return m_homing; }
    bool homingFailed() const { return m_homingFailed; }
    double speed() const { return m_motor.speed(); }
    // The speed magnitude the motion is heading for: a jog's target speed, a move's cruise speed.
    double cruiseSpeed() const;
    qint64 motorPosition() const { return m_motor.position(); }

    bool leftLimit() const;
    bool rightLimit() const;
    bool origin() const;

    qint64 absolutePosition() const { return commanded() - m_absOffset; }
    qint64 relativePosition() const { return commanded() - m_relOffset; }
    qint64 closedLoopAbsolute() const { return m_motor.position() - m_clAbsOffset; }
    qint64 closedLoopRelative() const { return m_motor.position() - m_clRelOffset; }
    void clearAbsolute() { m_absOffset = commanded(); }
    void clearRelative() { m_relOffset = commanded(); }
    void setClosedLoopAbsolute(qint64 v) { m_clAbsOffset = m_motor.position() - v; }
    void setClosedLoopRelative(qint64 v) { m_clRelOffset = m_motor.position() - v; }
    qint64 motorPositionForClosedLoop(qint64 closedLoopTarget) const { return closedLoopTarget + m_clAbsOffset; }
    // Puts the motor at `position` (at rest) and zeroes the counters there (tests, --state).
    void placeAt(qint64 position);

    QJsonObject save() const;
    void load(const QJsonObject &o);

    MotorModel &motor() { return m_motor; }
    const MotorModel &motor() const { return m_motor; }

private:
    qint64 commanded() const { return m_closedLoop ? m_motor.commandPosition() : m_motor.position(); }
    void stepOnce();
    void checkSwitches(double before, double after);
    void zeroCounters();

    MotorModel m_motor;
    Switches m_switches;
    bool m_closedLoop = true;
    qint64 m_nowUs = 0;
    qint64 m_absOffset = 0;
    qint64 m_relOffset = 0;
    qint64 m_clAbsOffset = 0;
    qint64 m_clRelOffset = 0;
    bool m_homing = false;
    bool m_homingFailed = false;
    bool m_homingReversed = false;
    int m_homingDir = 0;
    Homing m_homingHow = Homing::ReverseAtLimit;
    double m_homingSpeed = 0.0;
};

} // namespace dd
