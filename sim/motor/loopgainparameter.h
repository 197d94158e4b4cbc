#pragma once

#include "sim/motor/motormodel.h"

#include <QList>
#include <QString>
#include <functional>

namespace dd {

// One parameter a simulated drive reads its closed loop from. This is the simulator's own
// model (docs/tuning.md): the protocol seeds name no gain parameters, so nothing here says
// what a real drive's parameter of the same number does. The roles are the dictionaries'
// "tuning" roles (docs/dictionaries.md).
struct LoopGainParameter
{
    enum class Role {
        SpeedKp,           // "speed-kp": speed-loop gain, Hz (bandwidth)
        SpeedKi,           // "speed-ki": speed-loop integral gain, 1/s
        PositionKp,        // "position-kp": position-loop gain, 1/s
        SpeedFeedforward,  // "speed-feedforward": %, 0..100
        TorqueFeedforward, // "torque-feedforward": %, 0..100 (acceleration feed-forward)
        Acceleration       // "acceleration": r/min per ms, the reference's acceleration limit
    };
    int index = -1; // the drive's parameter number
    Role role = Role::SpeedKp;
    qint64 defaultValue = 0;
    qint64 min = 0;
    qint64 max = 0;

    static QString roleId(Role role);
    static QString unit(Role role);
};

// The loop gains the parameters say (values clamped to each entry's range), applied to
// `motor` if they differ from what it has. `value(index)` reads the drive's parameter.
void applyLoopGainParameters(const QList<LoopGainParameter> &table, const std::function<qint64(int)> &value,
                             MotorModel *motor);

} // namespace dd
