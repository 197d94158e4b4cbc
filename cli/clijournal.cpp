#include "cli/clijournal.h"

#include "cli/clicommand.h"
#include "core/drive/drive.h"
#include "core/report/verificationjournal.h"

#include <QFileInfo>

namespace dd {

QString CliJournal::link(const CliGlobals &globals)
{
    if (!globals.sim)
        return globals.connection.linkName();
    if (globals.simStateFile.isEmpty())
        return QStringLiteral("sim");
    return QStringLiteral("sim:") + QFileInfo(globals.simStateFile).absoluteFilePath();
}

JournalKey CliJournal::key(CliContext *context)
{
    const Drive *d = context->drive();
    return key(context, d ? d->identity() : DriveIdentity(), context->globals.address);
}

JournalKey CliJournal::key(CliContext *context, const DriveIdentity &identity, int address)
{
    DriveIdentity id = identity;
    id.family = context->globals.connection.family;
    id.address = address;
    return JournalKey::of(id, link(context->globals), context->globals.machine);
}

void CliJournal::verification(CliContext *context, const RecordVerification &verification)
{
    VerificationJournal journal;
    if (Error e = journal.recordVerification(key(context), verification))
        context->out->note(e.message);
}

void CliJournal::restore(CliContext *context, const JournalKey &key, const RestoreReport &report,
                         const ParameterDictionary &dictionary, const QString &path, const QString &checksum)
{
    VerificationJournal journal;
    if (Error e = journal.recordRestore(key, report, dictionary, path, checksum))
        context->out->note(e.message);
}

void CliJournal::ee(CliContext *context, const RecordEeOperation &operation)
{
    VerificationJournal journal;
    if (Error e = journal.recordEeOperation(key(context), operation))
        context->out->note(e.message);
}

void CliJournal::backup(CliContext *context, const QString &role, const QString &path, const QString &checksum)
{
    VerificationJournal journal;
    const BackupReference b{role, QFileInfo(path).absoluteFilePath(), checksum, QDateTime::currentDateTimeUtc()};
    if (Error e = journal.recordBackup(key(context), b))
        context->out->note(e.message);
}

} // namespace dd
