#pragma once

#include "core/common/error.h"
#include "core/common/family.h"
#include "core/report/backupreference.h"
#include "core/report/journalkey.h"
#include "core/report/recordeeoperation.h"
#include "core/report/recordverification.h"

#include <QCoreApplication>
#include <QList>
#include <QString>
#include <functional>

namespace dd {

class ParameterDictionary;
struct DriveRecord;
enum class EeOperation;
struct ParameterWriteResult;
struct RestoreReport;

// What the restore and write paths verified, kept between sessions so that a commissioning
// record made later can say it: per drive (JournalKey: machine name, family, address, link,
// firmware, model) the last restore or parameter write with every write's outcome, and the
// last backup files saved from or restored onto it with their checksums. One small JSON file
// per drive in <GenericDataLocation>/drivedesk/journal/ (docs/record.md); the CLI and the GUI
// share it. Every change is a read-modify-write under a QLockFile next to the file, written
// with QSaveFile (atomic replace): two processes never lose or interleave each other's
// entries. A missing journal reads as empty; a damaged one is reported, never overwritten.
class VerificationJournal
{
    Q_DECLARE_TR_FUNCTIONS(dd::VerificationJournal)
public:
    static constexpr int MaxBackups = 6;
    static constexpr int LockTimeoutMs = 20000; // how long a change waits for another process's

    struct Entry
    {
        RecordVerification verification;
        QList<BackupReference> backups; // newest first
        RecordEeOperation ee;
    };

    explicit VerificationJournal(const QString &directory = defaultDirectory());
    static QString defaultDirectory();
    QString directory() const { return m_directory; }

    // The drive's entry; empty when it has none. A file that is not a journal of this key
    // reads as empty with *error saying why (the file is left as it is).
    Entry read(const JournalKey &key, Error *error = nullptr) const;
    // Error (and nothing written) when the lock is not had in time, the journal is damaged
    // or cannot be written.
    Error recordVerification(const JournalKey &key, const RecordVerification &verification);
    Error recordBackup(const JournalKey &key, const BackupReference &backup);
    Error recordEeOperation(const JournalKey &key, const RecordEeOperation &operation);
    // A restore from a backup file (single drive or fleet; CLI and GUI): its verification
    // and the file as a "restore" backup reference, in one change. Nothing is noted for a
    // dry run or a restore that selected nothing.
    Error recordRestore(const JournalKey &key, const RestoreReport &report, const ParameterDictionary &dictionary,
                        const QString &file, const QString &checksum);
    QString path(const JournalKey &key) const;
    // Puts the key's last verification, backups and identification into *record (and
    // record->journalError when the journal is damaged).
    void attach(const JournalKey &key, DriveRecord *record) const;

    // The write paths' results as a verification ("write": Drive::writeParameters, the
    // GUI's and CLI's `set`; "restore": ParameterTransfer::restore).
    static RecordVerification fromWrites(const QList<ParameterWriteResult> &writes,
                                         const ParameterDictionary &dictionary);
    static RecordEeOperation fromEe(EeOperation operation, const Error &error);
    static RecordVerification fromRestore(const RestoreReport &report, const ParameterDictionary &dictionary,
                                          const QString &file, const QString &checksum);

private:
    Error update(const JournalKey &key, const std::function<void(Entry &)> &change);
    Error write(const JournalKey &key, const Entry &entry);

    QString m_directory;
};

} // namespace dd
