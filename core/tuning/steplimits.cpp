#include "core/tuning/steplimits.h"

#include "core/tuning/stepspec.h"

#include <cmath>

namespace dd {

Error StepLimits::check(const StepSpec &spec) const
{
    auto bad = [](const QString &message) { return Error{ErrorCode::InvalidArgument, message}; };
    const QString need = tr("A step test needs limits: a maximum speed, a maximum travel from the start position and "
                            "a maximum duration.");
    if (!(maxSpeed > 0.0))
        return bad(need + QLatin1Char(' ') + tr("The maximum speed is not set."));
    if (maxTravel <= 0)
        return bad(need + QLatin1Char(' ') + tr("The maximum travel is not set."));
    if (!(maxDurationS > 0.0))
        return bad(need + QLatin1Char(' ') + tr("The maximum duration is not set."));
    if (std::abs(double(spec.speed)) > maxSpeed)
        return bad(tr("The step's speed %1 is above the maximum speed %2.").arg(spec.speed).arg(maxSpeed));
    if (spec.kind == StepSpec::Kind::Position && std::abs(double(spec.distance)) > double(maxTravel))
        return bad(tr("The step's distance %1 is beyond the maximum travel %2.").arg(spec.distance).arg(maxTravel));
    if (spec.commandedSeconds() >= maxDurationS)
        return bad(tr("The step runs for %1 s, which leaves no time to stop within the maximum duration of %2 s.")
                       .arg(spec.commandedSeconds())
                       .arg(maxDurationS));
    return {};
}

} // namespace dd
