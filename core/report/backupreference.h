#pragma once

#include <QDateTime>
#include <QString>

namespace dd {

// A backup file that belongs to a drive's record: its own checksum (the "checksum" of the
// drivedesk-backup file, docs/backup-format.md) so that the file can be matched to paper.
struct BackupReference
{
    QString role; // "backup" (saved from the drive), "restore" (restored onto it)
    QString path;
    QString checksum; // "sha256:..."
    QDateTime when;
};

} // namespace dd
