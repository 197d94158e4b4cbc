#pragma once

#include "core/common/error.h"
#include "core/common/family.h"
#include "core/drive/restorereport.h"
#include "core/params/backupfile.h"

#include <QCoreApplication>
#include <QObject>

namespace dd {

class Drive;
class ParameterDictionary;
class ParameterTransfer;
struct TuningRun;

// "Apply this run's parameters" (docs/tuning.md): restores a run's tuning snapshot to the
// drive the way a backup restore does — ParameterTransfer reads the drive, writes only the
// snapshot's parameters whose value differs, and reads every write back; report() says what
// was written and verified. check() refuses a run of another family, a snapshot entry whose
// key no longer names that parameter in the drive's dictionary, a read-only parameter or a
// value out of range, before anything is sent. Another firmware is refused unless forced
// (as restore does).
class RunParameterApply : public QObject
{
    Q_OBJECT
public:
    explicit RunParameterApply(Drive *drive, QObject *parent = nullptr);
    ~RunParameterApply() override;

    // No I/O: may this run's snapshot go to a drive of `family` with dictionary `dict`?
    static Error check(const TuningRun &run, Family family, const ParameterDictionary &dict);
    // The snapshot as a backup file of the run's drive (family, address, firmware, model).
    static BackupFile snapshotFile(const TuningRun &run);

    // Starts; an error (nothing sent, no finished()) when check() refuses the run.
    Error apply(const TuningRun &run, bool dryRun = false, bool force = false);
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
