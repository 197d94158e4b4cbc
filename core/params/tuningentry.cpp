#include "core/params/tuningentry.h"

namespace dd {

const QStringList &TuningEntry::knownRoles()
{
    static const QStringList roles = {
        QStringLiteral("speed-kp"),           QStringLiteral("speed-ki"),     QStringLiteral("speed-kd"),
        QStringLiteral("position-kp"),        QStringLiteral("position-ki"),  QStringLiteral("position-kd"),
        QStringLiteral("current-kp"),         QStringLiteral("current-ki"),   QStringLiteral("speed-feedforward"),
        QStringLiteral("torque-feedforward"), QStringLiteral("speed-filter"), QStringLiteral("torque-filter"),
        QStringLiteral("notch-frequency"),    QStringLiteral("notch-width"),  QStringLiteral("notch-depth"),
        QStringLiteral("inertia-ratio"),      QStringLiteral("acceleration"), QStringLiteral("deceleration"),
    };
    return roles;
}

} // namespace dd
