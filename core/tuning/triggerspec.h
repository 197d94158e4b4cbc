#pragma once

#include "core/common/error.h"

#include <QCoreApplication>
#include <QString>

namespace dd {

// What starts a capture (docs/tuning.md): a channel crossing a level (rising, falling,
// either), a channel above or below a level, an alarm being raised, motion start (a step
// test's own command), or at once (manual / "now").
struct TriggerSpec
{
    Q_DECLARE_TR_FUNCTIONS(dd::TriggerSpec)

public:
    enum class Kind { Now, Rise, Fall, Either, Above, Below, Alarm, MotionStart };

    Kind kind = Kind::Now;
    QString channel; // level triggers
    double level = 0.0;

    bool isLevel() const
    {
        return kind == Kind::Rise || kind == Kind::Fall || kind == Kind::Either || kind == Kind::Above
            || kind == Kind::Below;
    }
    // Whether the pair of consecutive values (previous, current) fires a level trigger.
    // A crossing needs the previous value on the other side (or on the level): rise
    // fires when previous < level <= current.
    bool fires(double previous, double current) const;

    // "rise:speed:500", "fall:CH:V", "either:CH:V", "above:CH:V", "below:CH:V", "alarm",
    // "motion", "now"; with a translated reason on error (InvalidArgument).
    static Error parse(const QString &text, TriggerSpec *out);
    QString toString() const; // the same syntax
    static QString kindId(Kind kind);
};

} // namespace dd
