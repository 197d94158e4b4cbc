#pragma once

#include <QDateTime>
#include <QImage>
#include <QList>
#include <QString>

namespace dd {

// One tuning run the engineer chose for the record: what was measured, the parameters it
// ran with and its plot. The tuning work's run files (.ddrun) are turned into this.
struct RunRecord
{
    struct Metric
    {
        QString name; // "overshoot", in the record's language
        double value = 0;
        QString unit; // "%", "ms"
    };
    struct SnapshotValue
    {
        QString key;
        QString name;
        qint64 value = 0;
        QString unit;
    };

    QString title;
    QString file; // the run file it came from, if any
    QDateTime when;
    QList<Metric> metrics;
    QList<SnapshotValue> snapshot;
    QImage plot; // null: no plot
};

} // namespace dd
