#pragma once

#include "core/common/error.h"
#include "core/drive/restorereport.h"
#include "core/fleet/fleetdriveresult.h"
#include "core/params/backupfile.h"

#include <QList>
#include <QObject>
#include <QPointer>
#include <QVector>

namespace dd {

class Drive;
class ParameterTransfer;

// Backups and restores of several drives of one link: one ParameterTransfer per drive.
// By default all drives run at once: their requests queue on the link back to back (a
// serial link sends the next one as soon as the previous answer is in; a CAN link
// pipelines the reads of several stations together). With stopAtFirstFailure the drives
// run one after the other in the order given, and after a failed one the rest are not
// attempted. Each drive's result is its own: one drive failing (silent, refusing a value)
// does not stop the others unless asked to.
//  - backup(): each drive's identity and values (result.backup, result.values);
//  - restore(file, options): the same file to every drive (only the differences written,
//    each read back; communication settings only when options.only names them). A dry run
//    is the plan: result.report.selected per drive, nothing written. restoreEach(): the
//    same, each drive from its own file.
// finished() is emitted once, after every drive's result is final. Lives in the drives'
// thread.
class FleetTransfer : public QObject
{
    Q_OBJECT
public:
    explicit FleetTransfer(const QList<Drive *> &drives, QObject *parent = nullptr);
    ~FleetTransfer() override;

    void setStopAtFirstFailure(bool stop) { m_stopAtFirstFailure = stop; }
    bool stopsAtFirstFailure() const { return m_stopAtFirstFailure; }

    void backup();
    void restore(const BackupFile &file, const RestoreOptions &options);
    // Each drive from its own file (files[i] to the i-th drive: a backup folder put back).
    void restoreEach(const QVector<BackupFile> &files, const RestoreOptions &options);
    // No further drive is started; those under way finish (their reports stay complete).
    void cancel();
    // The link is gone: the drives not started are not attempted; those under way fail on
    // their own (their reports say what they wrote) or, after AbortGraceMs, with `why`.
    static constexpr int AbortGraceMs = 2000;
    void abort(const Error &why);

    bool isRunning() const { return m_running; }
    const QVector<FleetDriveResult> &results() const { return m_results; }
    // Every drive done.
    bool allDone() const;

signals:
    void driveStarted(int position);
    void driveFinished(int position);
    void progress(int drivesDone, int drives);
    void finished();

private:
    enum class Job { Backup, Restore };
    void begin(Job job);
    void startNext();
    void startDrive(int position);
    void onDriveFinished(int position, const Error &error);
    void finishIfDone();

    QList<QPointer<Drive>> m_drives;
    QVector<ParameterTransfer *> m_transfers;
    QVector<FleetDriveResult> m_results;
    Job m_job = Job::Backup;
    BackupFile m_file;
    QVector<BackupFile> m_files; // restoreEach(): one per drive
    RestoreOptions m_options;
    bool m_stopAtFirstFailure = false;
    bool m_running = false;
    bool m_stopping = false;
    Error m_abortError;
    int m_next = 0;
};

} // namespace dd
