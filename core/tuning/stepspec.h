#pragma once

#include "core/common/error.h"

#include <QCoreApplication>
#include <QStringList>
#include <optional>

namespace dd {

// What a step test does (docs/tuning.md):
//  - Velocity: run at `speed` for `durationS`, then stop.
//  - Position: move by `distance` (counts / pulses) at `speed`.
//  - Reversal: run at +`speed` for `durationS`, then at -`speed` for `durationS`, then stop.
// The capture starts `preS` before the motion command (the "motion" trigger) and records
// `recordS` after it (0: the commanded time plus `settleS`; a position step: until the axis
// is at rest, plus `settleS`, at most the maximum duration). The
// channels are those that matter for the test among what the drive offers, unless
// `channels` names them (speed and position are always added: the limits are watched on
// them). After a completed test the axis goes back to where it started, unless
// `returnToStart` is false (an aborted test leaves the axis where it stopped).
struct StepSpec
{
    Q_DECLARE_TR_FUNCTIONS(dd::StepSpec)

public:
    enum class Kind { Velocity, Position, Reversal };

    Kind kind = Kind::Velocity;
    qint32 speed = 0;       // drive speed unit; velocity / reversal: signed, position: > 0
    double durationS = 0.0; // velocity, reversal: the time at each speed
    qint64 distance = 0;    // position: relative move, signed, not 0
    double preS = 0.05;     // capture before the motion command
    double recordS = 0.0;   // capture after it (0: automatic)
    double settleS = 0.3;   // automatic record: this long after the commanded time
    bool returnToStart = true;
    // Counts per motor revolution, for drives whose speed unit is r/min (0: the assumption
    // StepPlan::DefaultCountsPerRev): how the test's travel is predicted before it moves.
    double countsPerRev = 0.0;
    QStringList channels; // empty: chosen for the drive (StepTest::channelsFor)

    // The capture after the motion command, seconds (0: a position step's, until at rest).
    double recordSeconds() const;
    // The commanded time of the motion (0 for a position step: it ends when it arrives).
    double commandedSeconds() const;
    // InvalidArgument when the spec itself is bad (speed 0, no duration, distance 0, ...).
    Error check() const;

    static QString kindId(Kind kind); // "velocity", "position", "reversal"
    static std::optional<Kind> kindFromId(const QString &id);
    // The run's "test" field: "velocity-step", "position-step", "reversal".
    static QString testId(Kind kind);
};

} // namespace dd
