#include "core/tuning/stepplan.h"

#include "core/tuning/steplimits.h"
#include "core/tuning/stepspec.h"

#include <cmath>

namespace dd {

double StepPlan::countsPerSpeedUnit(const QString &speedUnit, double countsPerRev)
{
    const QString u = speedUnit.trimmed().toLower();
    if (u == QLatin1String("pulse/s") || u == QLatin1String("counts/s") || u == QLatin1String("count/s"))
        return 1.0;
    if (u == QLatin1String("r/min") || u == QLatin1String("rpm"))
        return (countsPerRev > 0.0 ? countsPerRev : DefaultCountsPerRev) / 60.0;
    return 0.0;
}

double StepPlan::decelFromParameter(const QString &unit, double value)
{
    if (!(value > 0.0) || !std::isfinite(value))
        return 0.0;
    QString u = unit.trimmed().toLower();
    u.replace(QStringLiteral("²"), QStringLiteral("^2"));
    if (u == QLatin1String("r/min/ms"))
        return value * 1000.0;
    if (u == QLatin1String("r/min/s"))
        return value;
    if (u == QLatin1String("pulse/s^2") || u == QLatin1String("pulse/s/s") || u == QLatin1String("counts/s^2"))
        return value;
    return 0.0;
}

StepPlan StepPlan::predict(const StepSpec &spec, double countsPerSpeedUnitS, double decelPerS)
{
    StepPlan p;
    p.countsPerSpeedUnitS = countsPerSpeedUnitS;
    p.decelPerS = decelPerS > 0.0 ? decelPerS : std::numeric_limits<double>::infinity();
    const double v = std::abs(double(spec.speed));
    const double tStop = p.stopSeconds(v);
    const double countsPerS = v * countsPerSpeedUnitS;
    switch (spec.kind) {
    case StepSpec::Kind::Velocity:
        // The ramp up is left out (it only shortens the way): T at full speed, then the stop.
        p.travel = countsPerS * (spec.durationS + tStop / 2.0);
        p.seconds = spec.durationS + tStop;
        break;
    case StepSpec::Kind::Reversal:
        // Furthest from the start when the reversal has braked the first segment to rest.
        p.travel = countsPerS * (spec.durationS + tStop / 2.0);
        p.seconds = 2.0 * spec.durationS + tStop;
        break;
    case StepSpec::Kind::Position: {
        const double d = std::abs(double(spec.distance));
        p.travel = d;
        if (!(countsPerS > 0.0)) {
            p.seconds = std::numeric_limits<double>::infinity();
            break;
        }
        // A trapezoid (a triangle when short) at the deceleration both ways.
        const double a = std::isfinite(p.decelPerS) ? p.decelPerS * countsPerSpeedUnitS : 0.0;
        if (!(a > 0.0))
            p.seconds = d / countsPerS;
        else if (d >= countsPerS * countsPerS / a)
            p.seconds = d / countsPerS + countsPerS / a;
        else
            p.seconds = 2.0 * std::sqrt(d / a);
        break;
    }
    }
    return p;
}

double StepPlan::stopSeconds(double speed) const
{
    if (!std::isfinite(decelPerS) || !(decelPerS > 0.0))
        return 0.0;
    return std::abs(speed) / decelPerS;
}

double StepPlan::stoppingDistance(double countsPerS, double speed, double reactionS, bool accelerating,
                                  double speedCap) const
{
    const double v = std::abs(countsPerS);
    const double vu = std::abs(speed);
    const double tr = std::max(0.0, reactionS);
    if (!accelerating || !std::isfinite(decelPerS) || !(decelPerS > 0.0))
        return v * tr + v * stopSeconds(vu) / 2.0;
    // Still ramping up: by the time the stop acts the speed may be higher by decel × tr.
    const double vu1 = speedCap > 0.0 ? std::min(vu + decelPerS * tr, std::abs(speedCap)) : vu + decelPerS * tr;
    const double ratio = vu > 0.0 && v > 0.0 ? v / vu : countsPerSpeedUnitS; // counts/s per speed unit
    const double v1 = std::max(v, vu1 * ratio);
    return (v + v1) / 2.0 * tr + v1 * stopSeconds(vu1) / 2.0;
}

Error StepPlan::check(const StepLimits &limits) const
{
    // Without a deceleration (infinite) the prediction is the test at full speed, its stop
    // left out: a lower bound.
    const bool withStop = std::isfinite(decelPerS);
    const QString decel = decelSource.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(decelSource);
    if (travel > double(limits.maxTravel))
        return {ErrorCode::OutOfRange,
                (withStop ? tr("The test would take the axis about %1 from the start, including its stop%2: beyond the "
                               "maximum travel %3.")
                          : tr("The test would take the axis about %1 from the start before it even stops%2: beyond "
                               "the maximum travel %3."))
                        .arg(std::llround(travel))
                        .arg(decel)
                        .arg(limits.maxTravel)
                    + QLatin1Char(' ') + tr("Shorten the test or lower its speed.")};
    if (seconds >= limits.maxDurationS)
        return {ErrorCode::OutOfRange,
                (withStop ? tr("The test needs about %1 s until the axis is at rest, including its stop%2: not within "
                               "the maximum duration of %3 s.")
                          : tr("The test needs about %1 s of motion before it even stops%2: not within the maximum "
                               "duration of %3 s."))
                    .arg(seconds, 0, 'f', 2)
                    .arg(decel)
                    .arg(limits.maxDurationS)};
    return {};
}

} // namespace dd
