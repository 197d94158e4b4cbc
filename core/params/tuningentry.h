#pragma once

#include <QString>
#include <QStringList>

namespace dd {

// One entry of a dictionary's "tuning" group (docs/dictionaries.md): a parameter and the
// role it plays in the drive's control loops. The role names what the parameter does
// ("speed-kp"), so that tuning views, run snapshots and comparisons can speak of gains the
// same way across drives whose parameter numbers differ.
struct TuningEntry
{
    int index = -1; // the parameter
    QString role;   // one of knownRoles()

    // speed-kp, speed-ki, speed-kd, position-kp, position-ki, position-kd, current-kp,
    // current-ki, speed-feedforward, torque-feedforward, speed-filter, torque-filter,
    // notch-frequency, notch-width, notch-depth, inertia-ratio, acceleration, deceleration.
    static const QStringList &knownRoles();
};

} // namespace dd
