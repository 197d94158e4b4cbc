#pragma once

#include "core/tuning/capturedata.h"

#include <QCoreApplication>
#include <QJsonObject>
#include <QStringList>
#include <optional>

namespace dd {

// One figure of a step response, with the resolution the sampling allows, or no value and
// the reason why (the link samples too slowly, the response never settled, ...).
struct Metric
{
    std::optional<double> value;
    double resolution = 0.0; // in the metric's unit: what one sample interval means for it
    QString reason;          // why there is no value (translated)
};

// The metrics of a step response (docs/tuning.md): rise time 10–90 %, overshoot, settling
// time to ±2 % and ±5 %, steady-state error and ripple, peak following error, peak torque
// and current, and the sample interval they rest on. Times in seconds, overshoot in percent
// of the step, the others in their channel's unit.
struct StepMetrics
{
    Q_DECLARE_TR_FUNCTIONS(dd::StepMetrics)

public:
    // What is measured: `channel` (the response, e.g. "speed") steps at time 0 from where
    // it was before (the mean of the pre-trigger samples, else the first sample) toward
    // `target` (the command; NaN: the mean of the last fifth of the step window); the
    // step window ends at `stepEnd` (seconds after the trigger; NaN: the end of the record).
    struct Input
    {
        QString channel = QStringLiteral("speed");
        double target = std::numeric_limits<double>::quiet_NaN();
        double stepEnd = std::numeric_limits<double>::quiet_NaN();
        QString followingErrorChannel = QStringLiteral("position-error");
        QString torqueChannel = QStringLiteral("torque");
        QString currentChannel = QStringLiteral("current");
    };

    Metric riseTime;
    Metric overshoot;
    Metric settlingTime2;
    Metric settlingTime5;
    Metric steadyStateError;
    Metric steadyStateRipple;
    Metric peakFollowingError;
    Metric peakTorque;
    Metric peakCurrent;
    Metric sampleInterval;

    static StepMetrics compute(const CaptureData &capture, const Input &input);

    // The keys of docs/tuning.md / the CLI's --json: riseTime, overshoot, settlingTime2,
    // settlingTime5, steadyStateError, steadyStateRipple, peakFollowingError, peakTorque,
    // peakCurrent, sampleInterval.
    static const QStringList &keys();
    const Metric &byKey(const QString &key) const;
    Metric &byKey(const QString &key);
    // {"riseTime": 0.012 | null, ...}; resolutions as {"riseTime": 0.001, ...}; notes as
    // "riseTime: <reason>" lines.
    QJsonObject valuesJson() const;
    QJsonObject resolutionsJson() const;
    QStringList notes() const;
    // From a run file's objects; false (and *error) when a key is missing or not a number/null.
    static bool fromJson(const QJsonObject &values, const QJsonObject &resolutions, const QStringList &notes,
                         StepMetrics *out, QString *error);
};

} // namespace dd
