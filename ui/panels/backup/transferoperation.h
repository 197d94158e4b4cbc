#pragma once

#include "core/drive/drivehub.h"
#include "core/drive/restorereport.h"
#include "core/params/backupfile.h"
#include "core/params/parameterdiff.h"

#include <memory>

namespace dd {

class ParameterDictionary;

// The GUI's way to run the shared backup / compare / restore workflow (ParameterTransfer,
// the same the CLI uses) through DriveHub::run: each function returns a hub operation that
// creates a ParameterTransfer on the I/O thread, forwards its progress, and finishes one
// reply when it ends. The results are copied into `out` on the I/O thread before the reply
// finishes, so the hub's done callback (GUI thread) may read them.
struct TransferOutcome
{
    BackupFile backup;                                     // backup()
    ParameterDiff diff;                                    // compare() and restore()
    RestoreReport report;                                  // restore()
    std::shared_ptr<const ParameterDictionary> dictionary; // the one the drive uses
};

class TransferOperation
{
public:
    static DriveHub::Operation backup(std::shared_ptr<TransferOutcome> out);
    static DriveHub::Operation compare(const BackupFile &file, std::shared_ptr<TransferOutcome> out);
    static DriveHub::Operation restore(const BackupFile &file, const RestoreOptions &options,
                                       std::shared_ptr<TransferOutcome> out);
};

} // namespace dd
