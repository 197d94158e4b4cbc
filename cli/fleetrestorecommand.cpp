#include "cli/fleetrestorecommand.h"

#include "cli/backupcommands.h"
#include "cli/clidescribe.h"
#include "cli/clijournal.h"
#include "cli/fleetbackupcommand.h"
#include "cli/restoredescribe.h"

#include "core/fleet/fleettransfer.h"
#include "core/params/backupfile.h"
#include "core/params/parameterdictionary.h"
#include "core/report/journalkey.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

namespace dd {

bool FleetRestoreCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 1, 1, tr("a backup file"), error))
        return false;
    if (QFileInfo(inv.positionals.at(0)).isDir())
        return prepareFolder(inv, error);
    if (!prepareTargets(inv, error))
        return false;
    m_path = inv.positionals.at(0);
    if (!FileCommand::loadFile(context(), m_path, &m_file, error))
        return false;
    m_stopOnFailure = inv.has(QStringLiteral("stop-on-failure"));
    return RestoreCommand::parseOptions(inv, m_file, m_path, *context()->dictionary, &m_options, error);
}

bool FleetRestoreCommand::prepareFolder(const CliInvocation &inv, QString *error)
{
    // Everything is checked before the link is opened: the index, every file it names for
    // the drives restored (structure, checksum, family, ranges), and that each file is the
    // backup of the drive at the address the index gives.
    m_path = inv.positionals.at(0);
    const QDir dir(m_path);
    if (inv.has(QStringLiteral("from")) || inv.has(QStringLiteral("to"))) {
        *error = tr("restore %1: a backup folder names its drives; --from and --to do not apply.").arg(m_path);
        return false;
    }
    const QString indexPath = dir.filePath(QStringLiteral("index.json"));
    QFile f(indexPath);
    if (!f.open(QIODevice::ReadOnly)) {
        *error = tr("restore %1: the folder has no index.json (write one with backup --all -o %1): %2")
                     .arg(m_path, f.errorString());
        return false;
    }
    QJsonParseError pe;
    const QJsonObject index = QJsonDocument::fromJson(f.read(1 << 20), &pe).object();
    if (pe.error != QJsonParseError::NoError
        || index.value(QStringLiteral("format")).toString() != FleetBackupCommand::indexFormatName()) {
        *error = tr("restore %1: %2 is not the index of a backup folder (format \"%3\").")
                     .arg(m_path, indexPath, FleetBackupCommand::indexFormatName());
        return false;
    }
    if (index.value(QStringLiteral("formatVersion")).toInt() != 1) {
        *error = tr("restore %1: index format version %2 is not supported (this DriveDesk reads 1).")
                     .arg(m_path, index.value(QStringLiteral("formatVersion")).toVariant().toString());
        return false;
    }
    const Family linkFamily = context()->globals.connection.family;
    if (index.value(QStringLiteral("family")).toString() != familyId(linkFamily)) {
        *error = tr("restore %1: the folder holds backups of %2 drives; this link is for %3 drives.")
                     .arg(m_path, index.value(QStringLiteral("family")).toString(), familyId(linkFamily));
        return false;
    }
    QMap<int, QString> files; // address -> file name ("" when its backup failed)
    for (const QJsonValue &v : index.value(QStringLiteral("drives")).toArray()) {
        const int address = v.toObject().value(QStringLiteral("address")).toInt(-1);
        const QString name = v.toObject().value(QStringLiteral("file")).toString();
        if (address < 0 || name.contains(QLatin1Char('/')) || name.contains(QLatin1Char('\\'))) {
            *error = tr("restore %1: index.json lists a drive without a valid address or file name.").arg(m_path);
            return false;
        }
        files.insert(address, name);
    }
    if (files.isEmpty()) {
        *error = tr("restore %1: index.json lists no drive.").arg(m_path);
        return false;
    }
    QList<int> targets = context()->globals.addresses;
    for (int a : std::as_const(targets))
        if (!files.contains(a)) {
            *error = tr("restore %1: drive %2 is not in the folder's index.").arg(m_path).arg(a);
            return false;
        }
    if (targets.isEmpty())
        targets = files.keys();
    for (int a : std::as_const(targets)) {
        if (files.value(a).isEmpty()) {
            QStringList others;
            for (int b : std::as_const(targets))
                if (!files.value(b).isEmpty())
                    others << QString::number(b);
            *error = tr("restore %1: drive %2 has no file in the folder (its backup failed). Restore the others "
                        "with --address %3.")
                         .arg(m_path)
                         .arg(a)
                         .arg(others.join(QLatin1Char(',')));
            return false;
        }
        BackupFile file;
        const QString path = dir.filePath(files.value(a));
        if (!FileCommand::loadFile(context(), path, &file, error))
            return false;
        if (file.address() != a) {
            *error = tr("restore %1: %2 is the backup of the drive at address %3, but the index gives it to "
                        "address %4.")
                         .arg(m_path, files.value(a))
                         .arg(file.address())
                         .arg(a);
            return false;
        }
        if (!RestoreCommand::parseOptions(inv, file, path, *context()->dictionary, &m_options, error))
            return false;
        m_files.append(file);
        m_fileNames << files.value(a);
    }
    m_stopOnFailure = inv.has(QStringLiteral("stop-on-failure"));
    setTargets(targets);
    return true;
}

void FleetRestoreCommand::run(const QList<int> &addresses)
{
    newTransfer(addresses);
    m_transfer->setStopAtFirstFailure(m_stopOnFailure);
    connect(m_transfer, &FleetTransfer::finished, this, &FleetRestoreCommand::report);
    if (m_files.isEmpty())
        m_transfer->restore(m_file, m_options);
    else
        m_transfer->restoreEach(m_files, m_options);
}

void FleetRestoreCommand::report()
{
    const ParameterDictionary &dict = *context()->dictionary;
    QJsonArray drives;
    QStringList text;
    int done = 0;
    for (const FleetDriveResult &r : m_transfer->results()) {
        QJsonObject o = driveJson(r);
        const int position = int(drives.size());
        if (position < m_fileNames.size())
            o.insert(QStringLiteral("file"), m_fileNames.at(position));
        QList<QPair<QString, QString>> rows;
        o.insert(QStringLiteral("selected"), RestoreDescribe::selected(dict, r.report, &rows));
        RestoreDescribe::insertOutcomes(dict, r.report, &o);
        drives.append(o);
        if (r.state != FleetDriveResult::State::NotAttempted) { // for the commissioning record
            const bool each = position < m_files.size();
            const QString path = each ? QDir(m_path).filePath(m_fileNames.at(position)) : m_path;
            CliJournal::restore(context(), CliJournal::key(context(), r.identity, r.address), r.report, dict, path,
                                BackupFile::checksum((each ? m_files.at(position) : m_file).values()));
        }

        QString head;
        if (r.state == FleetDriveResult::State::Done) {
            ++done;
            if (r.report.selected.isEmpty())
                head = tr("drive %1: already matches the file; nothing to write.").arg(r.address);
            else if (r.report.dryRun)
                head = tr("drive %1: %n parameter(s) would be written.", nullptr, int(r.report.selected.size()))
                           .arg(r.address);
            else
                head = tr("drive %1: %n parameter(s) written and verified.", nullptr, int(r.report.written().size()))
                           .arg(r.address);
        } else {
            head = failureLine(r);
        }
        text << head;
        if (!rows.isEmpty())
            text << CliDescribe::table(rows).trimmed();
        if (r.state == FleetDriveResult::State::Failed && !r.report.selected.isEmpty() && !r.report.dryRun)
            text << RestoreDescribe::incomplete(dict, r.report);
    }
    const int n = int(m_transfer->results().size());
    text << (m_options.dryRun ? tr("Dry run on %n drive(s); nothing was sent.", nullptr, n)
                              : tr("%1 of %n drive(s) restored from %2.", nullptr, n).arg(done).arg(m_path));
    const QJsonObject json{{QStringLiteral("file"), m_path},
                           {QStringLiteral("dryRun"), m_options.dryRun},
                           {QStringLiteral("forced"), m_options.force},
                           {QStringLiteral("stopOnFailure"), m_stopOnFailure},
                           {QStringLiteral("drives"), drives}};
    conclude(json, text.join(QLatin1Char('\n')));
}

} // namespace dd
