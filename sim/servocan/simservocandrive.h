#pragma once

#include "sim/bench/simfamilies.h"
#include <QSet>

#include "core/protocol/servocan/servocan.h"
#include "sim/bus/simcandevice.h"
#include "sim/motor/loopgainparameter.h"
#include "sim/motor/motormodel.h"

#include <QJsonObject>

#include <array>

namespace dd {

// The drive side of the `servo-can` protocol (docs/protocols/servo-can.md) for SimCanBus.
//
// Parameters: 220 int16. The seed names P4 (control mode, 8 = internal run control),
// P74 (communication mode, 1 = CAN) and P75 (station); the defaults are P4 = 8, P74 = 1,
// P75 = station. The others get distinct deterministic values (-1000..2999, some negative)
// so that a shifted or swapped backup shows. Writes (0x15) take effect at once and read back;
// P75 accepts 0..99 only (other values are ignored, as a real drive refuses them) and, like
// on a real drive, the new station number is used after restart() only. setWriteProtected()
// makes the drive ignore writes to a parameter.
//
// Periodic frames: heartbeat every 30 ms while P74 = 1 (state 0x88 idle, 0x00 while the
// shaft turns or a motion command is active; absolute position); alarm frame (0x05) at once
// when the alarm code changes — also when it returns to 0, which the seed's "报警代码发生变化"
// covers — and every 2 s while alarmed.
//
// Watchdog: 2 s without a keep-alive (0x08) stops motion (decelerating at the model's
// limit); the servo stays enabled and holds the shaft. It is armed by each keep-alive and,
// for a host that sends none (a one-shot command from canbusutil), by each motion command.
//
// Motion (only while P74 = 1 and P4 = 8, else ignored): units are r/min for speeds and
// encoder counts for positions, countsPerRev() counts per revolution (10000 by default, the
// motor model's). 0x20 enables and runs at the speed; 0x21 / 0x22 enable and move at the 0x23
// positioning speed — with positioning speed 0 (the power-up value) they enable but do not
// move, as the seed says; 0x23 during a move changes its speed; 0x25 enables / disables;
// 0x26 decelerates to rest and stays enabled; 0x28 decelerates and disables at rest;
// 0x50 redefines the position; 0x81 clears the alarm (the servo stays disabled).
// Nothing is echoed: only 0x12 is answered. A frame whose b7 is not 0xFF (the seed's
// reserved checksum, "目前需固定的填入 0xff") is not taken.
//
// Closed loop (the simulator's own model, docs/tuning.md; the seed names no gain
// parameter): P60 speed-loop gain (Hz, default 30), P61 speed-loop integral gain (1/s, 30),
// P62 position-loop gain (1/s, 60), P63 speed feed-forward (%, 100), P64 acceleration of the
// speed and move profiles (r/min per ms, 6), P65 torque (acceleration) feed-forward (%, 100).
// loopGainParameters() lists them.
//
// Read values (0x12): speed r/min; position, position command, position error in counts;
// temperature °C; torque and torque command in % of rated; current in 0.01 A; speed command
// r/min; rotor position 0..countsPerRev-1; inputs as set by setInputs(); outputs bit 0 ready
// (no alarm), bit 1 enabled, bit 2 alarm, bit 3 in position (at rest); alarm code; bus
// voltage V.
class SimServoCanDrive : public SimCanDevice
{
public:
    using Parameters = std::array<qint16, servocan::kParameterCount>;

    struct Stats
    {
        quint64 framesForUs = 0;
        quint64 readsAnswered = 0;
        quint64 parameterWrites = 0;
        QSet<int> writtenIndexes; // every parameter written (a repeated write counts once)
        quint64 writesRefused = 0;
        quint64 keepAlives = 0;
        quint64 motionCommands = 0;
        quint64 commandsIgnored = 0; // motion while not in CAN mode (P74 / P4)
        quint64 heartbeatsSent = 0;
        quint64 alarmFramesSent = 0;
        quint64 watchdogTrips = 0;
    };

    // The motor runs the closed loop (MotorModel::closedLoopConfig()) whatever `motor` says.
    explicit SimServoCanDrive(int station, const MotorModel::Config &motor = MotorModel::Config());
    // The family's entry in the simulator table (sim/bench/simfamilies.h).
    static std::unique_ptr<SimCanDevice> create(const SimDeviceSpec &spec, Error *error);

    static Parameters defaultParameters(int station);
    // Which parameters the simulated closed loop reads (the simulator's model, not a drive's).
    static const QList<LoopGainParameter> &loopGainParameters();

    // SimCanDevice
    QList<CanFrameData> onCanFrame(const CanFrameData &frame, qint64 nowUs) override;
    QList<CanFrameData> tick(qint64 nowUs) override;
    QString describe() const override;
    void advanceTo(qint64 nowUs) override;

    int station() const { return m_station; }
    double countsPerRev() const { return m_motor.config().countsPerRev; }
    MotorModel &motor() { return m_motor; }
    const MotorModel &motor() const { return m_motor; }

    qint16 parameter(int index) const;
    void setParameter(int index, qint16 value);
    const Parameters &parameters() const { return m_params; }
    // Power cycle: the station number becomes P75, motion stops, the servo is disabled,
    // positioning speed 0, watchdog disarmed; parameters and the alarm stay.
    void restart();

    // Fault injection: the drive ignores writes to this parameter (as a drive may refuse a
    // value in its present state); a host sees it when it reads the value back.
    void setWriteProtected(int index, bool on);
    void injectAlarm(int code); // the drive disables; 0x05 goes out on the next tick (0: cleared)
    int alarmCode() const { return m_motor.alarmCode(); }
    void setInputs(quint32 bits) { m_inputs = bits; }
    qint32 positioningSpeed() const { return m_positioningSpeed; }

    bool isHostOnline() const { return m_hostOnline; } // keep-alive within the last 2 s
    qint64 lastKeepAliveUs() const { return m_lastKeepAliveUs; }
    const Stats &stats() const { return m_stats; }
    Stats &stats() { return m_stats; }

    // State for drivedesk-sim --state: {"station": N, "parameters": [220 ints], "position": P,
    // "alarm": code}. loadState() accepts what saveState() writes; it fails (returning false
    // and a technical English reason) without changing anything when the object is invalid.
    QJsonObject saveState() const;
    bool loadState(const QJsonObject &state, QString *error = nullptr);

private:
    QList<CanFrameData> answerRead(const servocan::Message &m);
    void handleWrite(const servocan::Message &m);
    void handleMotion(const servocan::Message &m, qint64 nowUs);
    bool canMode() const;
    bool heartbeatsOn() const;
    double rpmToCounts(qint32 rpm) const;
    qint32 countsToRpm(double countsPerSecond) const;
    qint32 outputs() const;

    int m_station;
    Parameters m_params;
    MotorModel m_motor;
    qint64 m_nowUs = 0;
    qint32 m_positioningSpeed = 0; // r/min, from 0x23
    bool m_disableAtRest = false;  // 0x28 in progress
    quint32 m_inputs = 0;
    std::array<bool, servocan::kParameterCount> m_writeProtected{};

    qint64 m_nextHeartbeatUs = 0;
    int m_reportedAlarm = 0;
    qint64 m_nextAlarmRepeatUs = -1;

    qint64 m_watchdogDeadlineUs = -1; // -1: disarmed
    qint64 m_lastKeepAliveUs = -1;
    bool m_hostOnline = false;
    Stats m_stats;
};

} // namespace dd
