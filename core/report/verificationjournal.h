#pragma once

#include "core/common/error.h"
#include "core/common/family.h"
#include "core/report/backupreference.h"
#include "core/report/recordverification.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

namespace dd {

class ParameterDictionary;
struct ParameterWriteResult;
struct RestoreReport;

// What the restore and write paths verified, kept between sessions so that a commissioning
// record made later can say it: per drive (family and address) the last restore or
// parameter write with every write's outcome, and the last backup files saved from or
// restored onto it with their checksums. One small JSON file per drive in
// <GenericDataLocation>/drivedesk/journal/ (docs/record.md); the CLI and the GUI share it.
// A missing or unreadable journal reads as empty (the record then says "none recorded").
class VerificationJournal
{
    Q_DECLARE_TR_FUNCTIONS(dd::VerificationJournal)
public:
    static constexpr int MaxBackups = 6;

    struct Entry
    {
        RecordVerification verification;
        QList<BackupReference> backups; // newest first
    };

    explicit VerificationJournal(const QString &directory = defaultDirectory());
    static QString defaultDirectory();
    QString directory() const { return m_directory; }

    Entry read(Family family, int address) const;
    Error recordVerification(Family family, int address, const RecordVerification &verification);
    Error recordBackup(Family family, int address, const BackupReference &backup);

    // The write paths' results as a verification ("write": Drive::writeParameters, the
    // GUI's and CLI's `set`; "restore": ParameterTransfer::restore).
    static RecordVerification fromWrites(const QList<ParameterWriteResult> &writes,
                                         const ParameterDictionary &dictionary);
    static RecordVerification fromRestore(const RestoreReport &report, const ParameterDictionary &dictionary,
                                          const QString &file, const QString &checksum);

private:
    QString path(Family family, int address) const;
    Error write(Family family, int address, const Entry &entry);

    QString m_directory;
};

} // namespace dd
