#pragma once

#include "core/common/error.h"
#include "core/common/family.h"
#include "core/drive/drivetypes.h"
#include "core/drive/restorereport.h"
#include "core/params/backupfile.h"
#include "core/params/tuningentry.h"

#include <QCoreApplication>
#include <QObject>
#include <QVector>

namespace dd {

class Drive;
class ParameterDictionary;
class ParameterTransfer;
struct TuningRun;

// "Apply this run's parameters" (docs/tuning.md): restores a run's tuning snapshot to the
// drive the way a backup restore does — ParameterTransfer reads the drive, writes only the
// snapshot's parameters whose value differs, and reads every write back; report() says what
// was written and verified.
//
// It writes tuning parameters only: check() refuses the whole run, before anything is sent,
// when any snapshot entry is not a tuning parameter in the dictionary in force for the drive
// (its role there is none — communication, mode, identity settings never are — naming every
// such entry), when that dictionary names no tuning parameters at all (a run recorded with
// the simulator's dictionary on a drive whose dictionary has no roles), when an entry has
// another key or role there than in the run (recorded with another dictionary), when a
// parameter is listed twice, for a run of another family, a read-only parameter or a value
// out of range; checkDrive() refuses a run of another drive model. Another firmware is
// refused unless forced (as restore does); --force never lifts the other refusals.
class RunParameterApply : public QObject
{
    Q_OBJECT
public:
    explicit RunParameterApply(Drive *drive, QObject *parent = nullptr);
    ~RunParameterApply() override;

    // No I/O: may this run's snapshot go to a drive of `family` with dictionary `dict`? The
    // tuning roles in force are dict.tuning(), or `roles` when given (the GUI's Tuning tab,
    // which shows the simulator's gains on a dictionary without a tuning group).
    static Error check(const TuningRun &run, Family family, const ParameterDictionary &dict,
                       const QVector<TuningEntry> *roles = nullptr);
    // No I/O: a run taken on another drive model than `identity`'s (when both are known).
    static Error checkDrive(const TuningRun &run, const DriveIdentity &identity);
    // The snapshot as a backup file of the run's drive (family, address, firmware, model).
    static BackupFile snapshotFile(const TuningRun &run);

    // Starts; an error (nothing sent, no finished()) when check() or checkDrive() refuses
    // the run (the drive's dictionary, with `roles` as in check()).
    Error apply(const TuningRun &run, bool dryRun = false, bool force = false,
                const QVector<TuningEntry> *roles = nullptr);
    bool isRunning() const;
    const RestoreReport &report() const;
    const ParameterDictionary &dictionary() const;
    const BackupFile &file() const { return m_file; }

signals:
    void progress(int done, int total);
    void finished(const dd::Error &error);

private:
    Drive *m_drive;
    ParameterTransfer *m_transfer;
    BackupFile m_file;
};

} // namespace dd
