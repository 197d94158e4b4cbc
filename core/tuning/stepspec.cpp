#include "core/tuning/stepspec.h"

#include <cmath>

namespace dd {

double StepSpec::commandedSeconds() const
{
    switch (kind) {
    case Kind::Velocity: return durationS;
    case Kind::Reversal: return 2.0 * durationS;
    case Kind::Position: break;
    }
    return 0.0;
}

double StepSpec::recordSeconds() const
{
    if (recordS > 0.0)
        return recordS;
    if (kind == Kind::Position)
        return 0.0;
    return commandedSeconds() + settleS;
}

Error StepSpec::check() const
{
    auto bad = [](const QString &message) { return Error{ErrorCode::InvalidArgument, message}; };
    if (kind == Kind::Position) {
        if (distance == 0)
            return bad(tr("A position step needs a distance other than 0."));
        if (speed <= 0)
            return bad(tr("A position step needs a speed above 0."));
    } else {
        if (speed == 0)
            return bad(tr("A %1 step needs a speed other than 0.").arg(kindId(kind)));
        if (!(durationS > 0.0) || durationS > 3600.0)
            return bad(tr("A %1 step needs a duration from 0 to 3600 s.").arg(kindId(kind)));
    }
    if (!(preS >= 0.0) || preS > 10.0)
        return bad(tr("The capture before the motion must be 0 to 10 s."));
    if (!(recordS >= 0.0) || recordS > 600.0)
        return bad(tr("The capture after the motion command must be 0 to 600 s."));
    if (!(countsPerRev >= 0.0) || countsPerRev > 1e9)
        return bad(tr("The counts per revolution must be 1 to 1000000000."));
    if (!(settleS >= 0.0) || settleS > 60.0)
        return bad(tr("The settling time recorded after the motion must be 0 to 60 s."));
    return {};
}

QString StepSpec::kindId(Kind kind)
{
    switch (kind) {
    case Kind::Velocity: return QStringLiteral("velocity");
    case Kind::Position: return QStringLiteral("position");
    case Kind::Reversal: return QStringLiteral("reversal");
    }
    return {};
}

std::optional<StepSpec::Kind> StepSpec::kindFromId(const QString &id)
{
    for (Kind k : {Kind::Velocity, Kind::Position, Kind::Reversal})
        if (id == kindId(k))
            return k;
    return std::nullopt;
}

QString StepSpec::testId(Kind kind)
{
    switch (kind) {
    case Kind::Velocity: return QStringLiteral("velocity-step");
    case Kind::Position: return QStringLiteral("position-step");
    case Kind::Reversal: return QStringLiteral("reversal");
    }
    return {};
}

} // namespace dd
