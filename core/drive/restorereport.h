#pragma once

#include "core/drive/drivetypes.h"
#include "core/params/parameterdiff.h"

#include <QList>
#include <QVector>

namespace dd {

// How a restore is to be done (ParameterTransfer::restore).
struct RestoreOptions
{
    QList<int> only;     // restrict to these parameters (empty: every difference)
    bool force = false;  // restore onto a drive with another (or unknown) firmware
    bool dryRun = false; // compare and select, write nothing
};

// What a restore did, parameter by parameter: the diff it started from, what it selected,
// and the outcome of every write. A selected parameter without a result was not attempted.
// A value type: copy it across threads freely.
struct RestoreReport
{
    enum class Outcome {
        Verified,     // written and read back equal
        WrittenOnly,  // written; write-only, so it cannot be read back
        Mismatch,     // written, but the read-back differs
        Failed,       // the drive did not accept the write
        NotAttempted, // the restore stopped before this parameter
        Unconfirmed   // no answer to the read-back: the value the drive holds is unknown
    };

    ParameterDiff diff;
    QVector<DiffEntry> selected;
    QList<ParameterWriteResult> results;
    bool dryRun = false;

    const ParameterWriteResult *result(int index) const;
    Outcome outcome(int index) const;
    QList<int> indices(Outcome outcome) const; // among `selected`, in order
    // Every selected parameter verified (or, write-only, written).
    bool isComplete() const;
    // "written" = Verified, WrittenOnly or Mismatch (the drive took a value); "not written"
    // = Failed or NotAttempted; Unconfirmed ones are in neither list.
    QList<int> written() const;
    QList<int> notWritten() const;

    static QString outcomeId(Outcome outcome); // "verified", "written-only", ...
};

} // namespace dd
