#pragma once

#include <QtGlobal>

namespace dd {

// One recorded value. timeUs is on the recorder's clock (whatever the sampler uses, e.g.
// DriveReply::sampleTimeUs()); only differences matter.
struct TrendSample
{
    qint64 timeUs = 0;
    double value = 0.0;

    friend bool operator==(const TrendSample &a, const TrendSample &b)
    {
        // Bitwise-equal doubles compare equal here; NaN never equals NaN (like double).
        return a.timeUs == b.timeUs && a.value == b.value;
    }
    friend bool operator!=(const TrendSample &a, const TrendSample &b) { return !(a == b); }
};

} // namespace dd
