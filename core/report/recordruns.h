#pragma once

#include "core/common/error.h"
#include "core/report/driverecord.h"
#include "core/tuning/tuningrun.h"

#include <QCoreApplication>
#include <QList>
#include <QLocale>

namespace dd {

// A run file (.ddrun) chosen for a commissioning record: loaded, checked, with the checksum of
// its bytes.
struct RecordRunFile
{
    QString path;
    QString checksum; // "sha256:<hex>"
    TuningRun run;
};

// Puts tuning runs into a commissioning record (docs/record.md, "Tuning runs"): loads a run
// file (a bad one is refused with the reason the loader gives), turns it into the record's
// RunRecord — its channels drawn by RunPlot, its step metrics with names and units, its
// parameter snapshot with the names and units of the drive's dictionary — and attaches each
// run to the drive it was taken on (same family and address).
class RecordRuns
{
    Q_DECLARE_TR_FUNCTIONS(dd::RecordRuns)
public:
    static Error load(const QString &path, RecordRunFile *out);
    // `drive` gives the parameters' names and units (its dictionary's); its family's bundled
    // dictionary where the drive has no parameters.
    static RunRecord toRecord(const RecordRunFile &file, const DriveRecord &drive, const QLocale &locale);
    // Attaches every run to its drive in `drives`. Refused (nothing attached) when a run's
    // drive is not among them, or a file is listed twice.
    static Error attach(const QList<RecordRunFile> &runs, QList<DriveRecord> *drives, const QLocale &locale);

    // "Velocity step", ... for a run file's test type, in the current translation.
    static QString testName(const QString &test);
    static QString metricName(const QString &key);
};

} // namespace dd
