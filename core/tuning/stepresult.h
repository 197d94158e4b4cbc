#pragma once

#include "core/common/error.h"
#include "core/tuning/tuningrun.h"

#include <QMetaType>

namespace dd {

// How a step test ended (StepTest::finished()).
struct StepResult
{
    enum class Outcome {
        Completed, // the motion ran, was captured and measured (`run`)
        Aborted,   // an alarm, STOP, a limit, a lost link or a failed capture ended it
        Failed     // it did not start moving: the drive's state or a refusal (nothing moved)
    };

    Outcome outcome = Outcome::Failed;
    QString reason; // translated: why it was aborted / failed ("" when completed)
    Error error;    // behind it: Cancelled (STOP, a limit), DriveException (alarm), LinkClosed, ...
    // "alarm", "stop", "external-stop", "speed-limit", "travel-limit", "duration-limit",
    // "link-lost", "capture-failed", "lease-expired", "stop-failed", "refused"; "" when not
    // aborted.
    QString abortCause;

    bool moved = false;         // a motion command was sent
    bool stopConfirmed = false; // the axis was seen at rest afterwards (or never moved)
    QString stoppedBy;          // the stop reply's "stoppedBy" ("command", "drive-watchdog", "nothing")
    QString stopNote;           // translated: where it stopped / why the stop is not confirmed

    bool positionKnown = false;
    qint64 startPosition = 0;
    qint64 endPosition = 0;
    bool returnedToStart = false; // back at the start position (within one count), read there
    qint64 farthest = 0;          // the largest distance from the start seen (counts), stop included

    // The prediction the test was let run on (StepPlan): travel (counts) and seconds; 0
    // when it never got that far.
    double predictedTravel = 0.0;
    double predictedSeconds = 0.0;
    QString decelSource; // translated: where the deceleration of the prediction came from

    bool hasRun = false; // `run` holds the capture, metrics and snapshot (a measured test)
    TuningRun run;

    bool completed() const { return outcome == Outcome::Completed; }
    static QString outcomeId(Outcome outcome); // "completed", "aborted", "failed"
};

} // namespace dd

Q_DECLARE_METATYPE(dd::StepResult)
