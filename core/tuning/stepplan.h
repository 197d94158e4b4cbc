#pragma once

#include "core/common/error.h"

#include <QCoreApplication>
#include <QString>
#include <limits>

namespace dd {

struct StepLimits;
struct StepSpec;

// What a step test will do to the axis, predicted before anything moves (docs/tuning.md,
// "Limits are bounds"): the largest distance from the start (travel, counts) and the time
// from the motion command until the axis is at rest, with the stopping distance at the
// drive's deceleration. A test whose prediction does not fit its limits is refused.
//
// Two figures link the speed unit to positions and to stops:
//  - countsPerSpeedUnitS: the counts one speed unit moves in one second (pulse/s: 1;
//    r/min: counts per revolution / 60 — the revolution's counts are not in any protocol
//    DriveDesk knows: StepSpec::countsPerRev, else the assumption DefaultCountsPerRev);
//  - decelPerS: the drive's deceleration, speed units per second (from its dictionary's
//    "deceleration" or "acceleration" role where the tuning snapshot holds it, else the
//    conservative assumption that a stop from the test's speed takes AssumedStopS).
struct StepPlan
{
    Q_DECLARE_TR_FUNCTIONS(dd::StepPlan)

public:
    static constexpr double DefaultCountsPerRev = 10000.0;
    static constexpr double AssumedStopS = 0.5;

    double countsPerSpeedUnitS = 0.0;
    double decelPerS = std::numeric_limits<double>::infinity(); // inf: stops not counted
    QString decelSource;                                        // translated, for messages
    double travel = 0.0;                                        // counts from the start, at most
    double seconds = 0.0;                                       // motion command → at rest

    // The counts per speed unit and second for a drive whose speed channel has `speedUnit`
    // ("r/min", "pulse/s", ...); countsPerRev 0: DefaultCountsPerRev. 0 when the unit is
    // unknown (then nothing can be predicted: the test is refused).
    static double countsPerSpeedUnit(const QString &speedUnit, double countsPerRev);
    // The deceleration (speed units / s) a parameter of `unit` with `value` gives, or 0 when
    // the unit is not one DriveDesk can convert ("r/min/ms", "r/min/s", "pulse/s²", ...).
    static double decelFromParameter(const QString &unit, double value);

    // The prediction for `spec` (decelPerS infinite: a lower bound, stops not counted).
    static StepPlan predict(const StepSpec &spec, double countsPerSpeedUnitS,
                            double decelPerS = std::numeric_limits<double>::infinity());
    // Seconds to stop from `speed` (speed units) at decelPerS.
    double stopSeconds(double speed) const;
    // The distance (counts) an axis moving at `countsPerS` needs to stop when its speed is
    // `speed` (speed units), after `reactionS` until the stop acts. `accelerating`: it may go
    // on gaining speed at the deceleration's rate until then (a jog's ramp, not yet at
    // `speedCap`, the commanded speed).
    double stoppingDistance(double countsPerS, double speed, double reactionS, bool accelerating = false,
                            double speedCap = 0.0) const;
    // OutOfRange (nothing moved: refused) naming the prediction and the limit it does not fit; none when it fits.
    Error check(const StepLimits &limits) const;
};

} // namespace dd
