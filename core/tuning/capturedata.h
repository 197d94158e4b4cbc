#pragma once

#include <QList>
#include <QString>
#include <QStringList>
#include <QVector>

namespace dd {

// Statistics of the intervals between consecutive samples (seconds).
struct IntervalStats
{
    int count = 0; // intervals (samples - 1)
    double mean = 0.0;
    double median = 0.0;
    double min = 0.0;
    double max = 0.0;

    static IntervalStats of(const QVector<double> &times);
};

// A stretch without samples much longer than the usual interval (times relative to the
// trigger): the link stalled, a reply was lost. Samples are never invented across it.
struct CaptureGap
{
    double from = 0.0; // the last sample before the gap
    double to = 0.0;   // the first sample after it
    // Gaps: intervals longer than three times the median interval.
    static QList<CaptureGap> of(const QVector<double> &times);
};

// What a capture recorded: samples as columns, time in seconds relative to the trigger
// (negative before it), each sample timestamped by its arrival.
struct CaptureData
{
    QStringList channels;
    QVector<double> time;
    QVector<QVector<double>> columns; // one per channel, time.size() values each (NaN: not read)
    int preTriggerSamples = 0;        // samples before time 0
    QString triggerSource;            // what fired: the trigger's text, "timeout", "manual", ...
    QList<CaptureGap> gaps;
    IntervalStats interval;

    bool isEmpty() const { return time.isEmpty(); }
    int columnOf(const QString &channel) const { return int(channels.indexOf(channel)); }
};

} // namespace dd
