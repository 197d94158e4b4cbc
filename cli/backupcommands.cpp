#include "cli/backupcommands.h"

#include "cli/clidescribe.h"
#include "cli/clijournal.h"
#include "cli/clivalues.h"
#include "cli/restoredescribe.h"
#include "core/protocol/familytraits.h"

#include "core/drive/drive.h"
#include "core/drive/parametertransfer.h"
#include "core/fleet/defaultvalues.h"
#include "core/params/parameterdictionary.h"
#include "core/report/verificationjournal.h"

#include <QDir>
#include <QFileInfo>

namespace dd {

// --- backup -----------------------------------------------------------------------------

bool BackupCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 0, 0, QString(), error))
        return false;
    m_changedOnly = inv.has(QStringLiteral("changed-only"));
    m_path = inv.value(QStringLiteral("output"));
    if (m_path.isEmpty()) {
        *error = tr("backup needs the file to write: backup -o FILE.");
        return false;
    }
    const QFileInfo info(m_path);
    if (!info.absoluteDir().exists()) {
        *error = tr("backup: the folder %1 does not exist.").arg(info.absolutePath());
        return false;
    }
    if (info.isDir()) {
        *error = tr("backup: %1 is a folder; give a file name.").arg(m_path);
        return false;
    }
    return true;
}

void BackupCommand::complete(BackupFile *file, const ConnectionSettings &c, const ParameterDictionary &dict,
                             bool changedOnly)
{
    QJsonObject link = file->link();
    if (c.isCan()) {
        link.insert(QStringLiteral("can"), c.can);
        if (c.bitrate)
            link.insert(QStringLiteral("bitrate"), c.bitrate);
    } else if (!c.port.isEmpty()) {
        link.insert(QStringLiteral("port"), c.port);
        if (c.baud)
            link.insert(QStringLiteral("baud"), c.baud);
    }
    if (!c.framing.isEmpty())
        link.insert(QStringLiteral("framing"), c.framing);
    file->setLink(link);
    if (changedOnly) {
        file->setValues(DefaultValues::changedOnly(dict, file->values()));
        file->setChangedOnly(true);
    }
}

void BackupCommand::start()
{
    m_transfer = new ParameterTransfer(drive(), this);
    connect(m_transfer, &ParameterTransfer::finished, this, [this](const Error &error) {
        if (error)
            return fail(error);
        BackupFile file = m_transfer->backupFile();
        complete(&file, context()->globals.connection, m_transfer->dictionary(), m_changedOnly);
        if (Error e = file.save(m_path, m_transfer->dictionary()))
            return fail(e, {}, CliExit::DriveFailed);
        CliJournal::backup(context(), QStringLiteral("backup"), m_path, BackupFile::checksum(file.values()));
        const int n = file.values().size();
        succeed({{QStringLiteral("file"), m_path},
                 {QStringLiteral("parameters"), n},
                 {QStringLiteral("changedOnly"), m_changedOnly},
                 {QStringLiteral("firmware"), file.firmware()},
                 {QStringLiteral("model"), file.model()}},
                m_changedOnly ? tr("%n parameter(s) changed from the defaults saved to %1.", nullptr, n).arg(m_path)
                              : tr("%n parameter(s) saved to %1.", nullptr, n).arg(m_path));
    });
    m_transfer->backup();
}

// --- diff and restore: the file ---------------------------------------------------------

bool FileCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 1, 1, tr("a backup file"), error))
        return false;
    m_path = inv.positionals.at(0);
    return loadFile(context(), m_path, &m_file, error);
}

bool FileCommand::loadFile(const CliContext *context, const QString &path, BackupFile *file, QString *error)
{
    // Everything is checked here, before the link is opened: structure, checksum, family,
    // indices and ranges (against the dictionary in use).
    if (Error e = file->load(path, context->dictionary.get())) {
        *error = e.message;
        return false;
    }
    const Family linkFamily = context->globals.connection.family;
    if (file->family() && *file->family() != linkFamily) {
        *error = tr("%1 is a backup of a %2 drive; this link is for %3 drives. A backup is "
                    "never restored onto another family; to talk to a %2 drive add --family %2.")
                     .arg(path, familyId(*file->family()), familyId(linkFamily));
        return false;
    }
    return true;
}

QJsonArray FileCommand::diffJson() const
{
    QJsonArray list;
    for (const DiffEntry &e : m_transfer->diff().entries()) {
        QJsonObject o{{QStringLiteral("index"), e.index},
                      {QStringLiteral("key"), e.key},
                      {QStringLiteral("status"), diffStatusId(e.status)},
                      {QStringLiteral("file"), CliValues::json(e.fileValue)},
                      {QStringLiteral("drive"), CliValues::json(e.driveValue)}};
        if (e.communication)
            o.insert(QStringLiteral("communication"), true);
        list.append(o);
    }
    return list;
}

QString FileCommand::diffText(bool onlyDifferences) const
{
    const ParameterDictionary &dict = m_transfer->dictionary();
    QList<QPair<QString, QString>> rows;
    for (const DiffEntry &e : m_transfer->diff().entries()) {
        if (onlyDifferences && e.status == DiffStatus::Same)
            continue;
        QString what;
        switch (e.status) {
        case DiffStatus::Same: what = tr("same"); break;
        case DiffStatus::Different: what = tr("differs"); break;
        case DiffStatus::OnlyInFile: what = tr("drive value unknown"); break;
        case DiffStatus::OnlyOnDrive: what = tr("not in the file"); break;
        case DiffStatus::NotReadable: what = tr("write-only: drive value not readable"); break;
        }
        if (e.communication)
            what += tr(" (communication setting)");
        rows.append(
            {dict.label(e.index),
             tr("file %1  drive %2  %3").arg(CliValues::text(e.fileValue), CliValues::text(e.driveValue), what)});
    }
    return CliDescribe::table(rows);
}

// --- diff -------------------------------------------------------------------------------

CliExit diffExitForFailure(const Error &error)
{
    return exitFor(error) == CliExit::OpenFailed ? CliExit::OpenFailed : CliExit::Usage;
}

void DiffCommand::start()
{
    m_transfer = new ParameterTransfer(drive(), this);
    connect(m_transfer, &ParameterTransfer::finished, this, [this](const Error &error) {
        if (error)
            return fail(error);
        const ParameterDiff &d = m_transfer->diff();
        const int differ = d.count(DiffStatus::Different);
        const int same = d.count(DiffStatus::Same);
        const QJsonObject json{{QStringLiteral("file"), m_path},
                               {QStringLiteral("different"), differ},
                               {QStringLiteral("same"), same},
                               {QStringLiteral("onlyInFile"), d.count(DiffStatus::OnlyInFile)},
                               {QStringLiteral("onlyOnDrive"), d.count(DiffStatus::OnlyOnDrive)},
                               {QStringLiteral("notReadable"), d.count(DiffStatus::NotReadable)},
                               {QStringLiteral("parameters"), diffJson()}};
        QString text = diffText(true);
        text += tr("%1 differ, %2 same (%3).").arg(differ).arg(same).arg(m_path);
        succeed(json, text, differ > 0 ? CliExit::DriveFailed : CliExit::Ok);
    });
    m_transfer->compare(m_file);
}

// --- restore ----------------------------------------------------------------------------

bool RestoreCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!FileCommand::prepare(inv, error))
        return false;
    return parseOptions(inv, m_file, m_path, *context()->dictionary, &m_options, error);
}

bool RestoreCommand::parseOptions(const CliInvocation &inv, const BackupFile &file, const QString &path,
                                  const ParameterDictionary &dict, RestoreOptions *options, QString *error)
{
    options->dryRun = inv.has(QStringLiteral("dry-run"));
    options->force = inv.has(QStringLiteral("force"));
    if (inv.has(QStringLiteral("only"))) {
        if (Error e = dict.resolveList({inv.value(QStringLiteral("only"))}, &options->only)) {
            *error = e.message;
            return false;
        }
        for (int i : std::as_const(options->only)) {
            if (!file.values().isKnown(i)) {
                *error = tr("restore --only: %1 has no value in %2.").arg(dict.label(i), path);
                return false;
            }
            const ParameterInfo *p = dict.byIndex(i);
            if (p && !p->isWritable()) {
                *error = tr("restore --only: %1 is read-only.").arg(dict.label(i));
                return false;
            }
        }
    }
    return true;
}

void RestoreCommand::start()
{
    m_transfer = new ParameterTransfer(drive(), this);
    connect(m_transfer, &ParameterTransfer::finished, this, &RestoreCommand::report);
    m_transfer->restore(m_file, m_options);
}

void RestoreCommand::interrupt(int)
{
    out()->note(tr("Finishing the restore in progress so that its report is complete; "
                   "every write is verified as it goes."));
}

void RestoreCommand::report(const Error &error)
{
    const ParameterDictionary &dict = m_transfer->dictionary();
    const RestoreReport &r = m_transfer->report();

    QList<QPair<QString, QString>> rows;
    QJsonObject json{{QStringLiteral("file"), m_path},
                     {QStringLiteral("dryRun"), r.dryRun},
                     {QStringLiteral("forced"), m_options.force},
                     {QStringLiteral("selected"), RestoreDescribe::selected(dict, r, &rows)}};
    RestoreDescribe::insertOutcomes(dict, r, &json);
    CliJournal::restore(context(), CliJournal::key(context()), r, dict, m_path, BackupFile::checksum(m_file.values()));

    if (error) {
        if (!r.selected.isEmpty() && !out()->isJson()) {
            out()->line(CliDescribe::table(rows));
            for (const QString &line : RestoreDescribe::incomplete(dict, r))
                out()->line(line);
        }
        return fail(error, json);
    }
    if (r.selected.isEmpty())
        return succeed(json, tr("The drive already matches %1; nothing to write.").arg(m_path));
    QString text = CliDescribe::table(rows);
    if (r.dryRun) {
        text += tr("Dry run: %n parameter(s) would be written; nothing was sent.", nullptr, int(r.selected.size()));
    } else {
        text += tr("%n parameter(s) written and verified.", nullptr, int(r.written().size()));
        if (familyTraits(context()->globals.connection.family).eeOperations)
            out()->note(tr("The values are in the drive's RAM; `ee set` stores them to EEPROM."));
    }
    succeed(json, text);
}

} // namespace dd
