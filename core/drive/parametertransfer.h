#pragma once

#include "core/common/error.h"
#include "core/drive/restorereport.h"
#include "core/params/backupfile.h"
#include "core/params/parameterdiff.h"
#include "core/params/parameterset.h"

#include <QObject>
#include <QPointer>
#include <memory>

namespace dd {

class Drive;
class DriveReply;
class ParameterDictionary;

// Backup, compare and restore of a drive's parameters: the workflow the CLI's backup /
// diff / restore commands and the GUI's backup page share.
//  - backup(): identify the drive, read every readable parameter, fill backupFile();
//    write-only settings the drive reports as last written (reply info "lastWritten")
//    are kept too, marked as such.
//  - compare(file): read the drive, diff() = the file against the drive.
//  - restore(file, options): refuse another family (always) and another firmware (unless
//    forced); read the drive; select the differences (RestoreOptions::only narrows them);
//    write them, each read back by the drive (Drive::writeParameters); report() says what
//    was written and verified and what not.
// Each runs asynchronously and ends with finished() (once). Lives in the drive's thread;
// the results are value types that may be copied to another thread.
class ParameterTransfer : public QObject
{
    Q_OBJECT
public:
    explicit ParameterTransfer(Drive *drive, QObject *parent = nullptr);
    ~ParameterTransfer() override;

    // The dictionary used: the drive's, else the bundled one of the drive's family.
    const ParameterDictionary &dictionary() const;

    // Where a job is, or where it stopped when it failed.
    enum class Stage { Idle, Identify, Read, Write };
    Stage stage() const { return m_stage; }
    static QString stageId(Stage stage); // "idle", "identify", "read", "write"

    void backup();
    void compare(const BackupFile &file);
    void restore(const BackupFile &file, const RestoreOptions &options);
    bool isRunning() const { return m_running; }

    const BackupFile &backupFile() const { return m_backup; }
    const ParameterSet &driveValues() const { return m_driveValues; }
    const ParameterDiff &diff() const { return m_report.diff; }
    const RestoreReport &report() const { return m_report; }

    // The parameters read from a drive: readable ones, and of those marked for particular
    // models only the ones for `model` (none of them when the model is unknown).
    static QList<int> readableIndices(const ParameterDictionary &dictionary, const QString &model);

signals:
    void progress(int done, int total);
    void finished(const dd::Error &error);

private:
    enum class Job { Backup, Compare, Restore };
    void begin(Job job);
    void identify();
    void readValues();
    void afterRead();
    void write();
    void end(const Error &error);
    void watch(DriveReply *reply, void (ParameterTransfer::*next)(DriveReply *));
    void onIdentified(DriveReply *reply);
    void onRead(DriveReply *reply);
    void onWritten(DriveReply *reply);

    QPointer<Drive> m_drive;
    std::shared_ptr<const ParameterDictionary> m_dictionary;
    Job m_job = Job::Backup;
    bool m_running = false;
    Stage m_stage = Stage::Idle;
    BackupFile m_file; // compare / restore: the file
    RestoreOptions m_options;
    BackupFile m_backup; // backup: the result
    ParameterSet m_driveValues;
    RestoreReport m_report;
};

} // namespace dd
