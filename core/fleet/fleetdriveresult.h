#pragma once

#include "core/common/error.h"
#include "core/drive/drivetypes.h"
#include "core/drive/restorereport.h"
#include "core/params/backupfile.h"
#include "core/params/parameterset.h"

#include <QString>

namespace dd {

// What became of one drive in a FleetTransfer. A value type: copy it across threads freely.
struct FleetDriveResult
{
    enum class State {
        Pending,     // not started yet
        Running,     // under way
        Done,        // finished: the backup / read / restore is complete and verified
        Failed,      // stopped with `error`; `stoppedAt` and `report` say where
        NotAttempted // never started: an earlier drive failed (stop at the first failure),
                     // the run was cancelled, or the link went away first
    };

    int address = 0;
    State state = State::Pending;
    Error error;
    QString stoppedAt; // failed: the stage ("identify", "read", "write")
    DriveIdentity identity;
    ParameterSet values;  // backup / read / restore: the drive's values as read
    BackupFile backup;    // backup: the file's content
    RestoreReport report; // restore (also a dry run): what was selected and what became of it

    bool isFinished() const { return state == State::Done || state == State::Failed || state == State::NotAttempted; }
    static QString stateId(State state); // "pending", "running", "done", "failed", "not-attempted"
};

} // namespace dd
