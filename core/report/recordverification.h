#pragma once

#include <QDateTime>
#include <QList>
#include <QString>

namespace dd {

// The last restore or parameter write on a drive and how each write ended, as the restore
// and write paths report it (WriteVerification): kept in the VerificationJournal and shown
// in the commissioning record.
struct RecordVerification
{
    struct Entry
    {
        int index = 0;
        QString key;
        qint64 requested = 0;
        bool hasReadBack = false;
        qint64 readBack = 0;
        QString outcome; // "verified", "written-only", "mismatch", "failed", "not-attempted", "unconfirmed"
        QString message; // why, when not verified (as the tool said it)

        bool isVerified() const;
    };

    QString kind; // "restore" or "write"
    QDateTime when;
    QString sourceFile;     // restore: the backup file
    QString sourceChecksum; // restore: the backup file's checksum ("sha256:...")
    QList<Entry> entries;

    bool isEmpty() const { return kind.isEmpty(); }
    int failedCount() const; // entries not verified (written-only counts as verified)
    bool passed() const { return !isEmpty() && failedCount() == 0; }
};

} // namespace dd
