#pragma once

#include "core/tuning/triggerspec.h"

#include <optional>

namespace dd {

// How a capture is taken: its trigger, the share of the record before the trigger, the
// record's length, and what happens after (docs/tuning.md).
struct CaptureSettings
{
    enum class Mode {
        Single, // one capture, then stop
        Normal, // re-arm after each capture
        Auto    // like single, but capture anyway when no trigger came within the time-out
    };

    TriggerSpec trigger;
    double prePercent = 0.0; // 0..100 % of the record before the trigger
    double durationS = 1.0;  // the whole record, seconds
    Mode mode = Mode::Single;
    double timeoutS = 1.0; // auto: after this long armed without a trigger

    double preSeconds() const { return durationS * prePercent / 100.0; }
    double postSeconds() const { return durationS - preSeconds(); }

    static QString modeId(Mode mode); // "single", "normal", "auto"
    static std::optional<Mode> modeFromId(const QString &id);
};

} // namespace dd
