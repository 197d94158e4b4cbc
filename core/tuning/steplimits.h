#pragma once

#include "core/common/error.h"

#include <QCoreApplication>

namespace dd {

struct StepSpec;

// The limits a step test may not exceed (docs/tuning.md). A step test refuses to start
// without all three, before anything is sent: the maximum speed (in the drive's speed unit,
// the one jog and the "speed" channel use: r/min on the servos, pulse/s on shuoke), the
// maximum travel from the start position (position counts / pulses) and the maximum
// duration of the motion (seconds from the motion command until the axis is at rest).
// During the test the captured speed and position are watched against them.
struct StepLimits
{
    Q_DECLARE_TR_FUNCTIONS(dd::StepLimits)

public:
    double maxSpeed = 0.0;     // > 0
    qint64 maxTravel = 0;      // > 0
    double maxDurationS = 0.0; // > 0

    bool isSet() const { return maxSpeed > 0.0 && maxTravel > 0 && maxDurationS > 0.0; }
    // InvalidArgument naming the first missing limit, or the first thing `spec` asks for
    // beyond them (its speed, its distance, its commanded time); none when the test fits.
    Error check(const StepSpec &spec) const;
};

} // namespace dd
