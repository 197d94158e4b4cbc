#pragma once

#include <QDateTime>
#include <QImage>
#include <QList>
#include <QString>
#include <optional>

namespace dd {

// One tuning run the engineer chose for the record: what was measured, the parameters it
// ran with and its plot. RecordRuns turns a run file (.ddrun) into this.
struct RunRecord
{
    struct Metric
    {
        QString key;                 // "overshoot" (StepMetrics' keys)
        QString name;                // "Overshoot", in the record's language
        std::optional<double> value; // none: not measured (`note` says why)
        QString unit;                // "%", "ms", the channel's unit
        QString note;                // why there is no value
    };
    struct SnapshotValue
    {
        QString key;
        QString name;
        qint64 value = 0;
        QString unit;
    };

    QString title;
    QString file;     // the run file it came from, if any
    QString checksum; // "sha256:<hex>" of the run file's bytes ("" when not from a file)
    QString test;     // "capture", "velocity-step", "position-step", "reversal"
    QDateTime when;
    // How the capture was sampled: its samples, the mean interval between them, and the
    // stretches without samples (CaptureGap: over three median intervals).
    int samples = 0;
    double meanIntervalMs = 0;
    int gaps = 0;
    double longestGapMs = 0;
    QList<Metric> metrics;
    QList<SnapshotValue> snapshot;
    QImage plot; // null: no plot
};

} // namespace dd
