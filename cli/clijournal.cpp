#include "cli/clijournal.h"

#include "cli/clicommand.h"
#include "core/report/verificationjournal.h"

#include <QFileInfo>

namespace dd {

void CliJournal::verification(CliContext *context, const RecordVerification &verification)
{
    VerificationJournal journal;
    if (Error e = journal.recordVerification(context->globals.connection.family, context->globals.address,
                                             verification))
        context->out->note(e.message);
}

void CliJournal::backup(CliContext *context, const QString &role, const QString &path, const QString &checksum)
{
    VerificationJournal journal;
    const BackupReference b{role, QFileInfo(path).absoluteFilePath(), checksum, QDateTime::currentDateTimeUtc()};
    if (Error e = journal.recordBackup(context->globals.connection.family, context->globals.address, b))
        context->out->note(e.message);
}

} // namespace dd
