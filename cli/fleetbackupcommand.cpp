#include "cli/fleetbackupcommand.h"

#include "cli/backupcommands.h"
#include "cli/clidescribe.h"

#include "core/fleet/fleettransfer.h"
#include "core/params/parameterdictionary.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSaveFile>

namespace dd {

QString FleetBackupCommand::indexFormatName()
{
    return QStringLiteral("drivedesk-backup-index");
}

bool FleetBackupCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 0, 0, QString(), error) || !prepareTargets(inv, error))
        return false;
    m_changedOnly = inv.has(QStringLiteral("changed-only"));
    m_dir = inv.value(QStringLiteral("output"));
    if (m_dir.isEmpty()) {
        *error = tr("backup of several drives needs the folder to write to: backup --all -o DIR.");
        return false;
    }
    const QFileInfo info(m_dir);
    if (info.exists() && !info.isDir()) {
        *error = tr("backup: %1 is a file; several drives are saved into a folder (-o DIR).").arg(m_dir);
        return false;
    }
    if (!info.exists() && !QFileInfo(info.absolutePath()).isDir()) {
        *error = tr("backup: the folder %1 does not exist.").arg(info.absolutePath());
        return false;
    }
    return true;
}

QString FleetBackupCommand::fileName(int address) const
{
    return QStringLiteral("%1-%2.json").arg(familyId(context()->globals.connection.family)).arg(address);
}

void FleetBackupCommand::run(const QList<int> &addresses)
{
    newTransfer(addresses);
    connect(m_transfer, &FleetTransfer::finished, this, &FleetBackupCommand::save);
    m_transfer->backup();
}

CliExit FleetBackupCommand::exitOf(const FleetDriveResult &result) const
{
    if (result.state == FleetDriveResult::State::Done && m_saveErrors.contains(result.address))
        return CliExit::DriveFailed;
    return FleetCommand::exitOf(result);
}

void FleetBackupCommand::save()
{
    const ParameterDictionary &dict = *context()->dictionary;
    const QDir dir(m_dir);
    if (!dir.exists() && !QDir().mkpath(m_dir))
        return fail({ErrorCode::FileError, tr("backup: cannot create the folder %1.").arg(m_dir)}, {},
                    CliExit::DriveFailed);
    QJsonArray drives;
    QList<QPair<QString, QString>> rows;
    int saved = 0;
    for (const FleetDriveResult &r : m_transfer->results()) {
        QJsonObject o = driveJson(r);
        if (r.state != FleetDriveResult::State::Done) {
            drives.append(o);
            rows.append({tr("drive %1").arg(r.address), failureLine(r)});
            continue;
        }
        BackupFile file = r.backup;
        BackupCommand::complete(&file, context()->globals.connection, dict, m_changedOnly);
        const QString name = fileName(r.address);
        if (Error e = file.save(dir.filePath(name), dict)) {
            m_saveErrors.insert(r.address, e);
            o.insert(QStringLiteral("result"), QStringLiteral("failed"));
            o.insert(QStringLiteral("exitCode"), int(CliExit::DriveFailed));
            o.insert(QStringLiteral("error"), CliOutput::errorJson(e));
            drives.append(o);
            rows.append({tr("drive %1").arg(r.address), e.message});
            continue;
        }
        ++saved;
        o.insert(QStringLiteral("file"), name);
        o.insert(QStringLiteral("parameters"), file.values().size());
        o.insert(QStringLiteral("checksum"), BackupFile::checksum(file.values()));
        drives.append(o);
        rows.append(
            {tr("drive %1").arg(r.address), tr("%n parameter(s) -> %1", nullptr, file.values().size()).arg(name)});
    }

    QJsonObject link;
    const ConnectionSettings &c = context()->globals.connection;
    if (c.isCan())
        link.insert(QStringLiteral("can"), c.can);
    else if (!c.port.isEmpty())
        link.insert(QStringLiteral("port"), c.port);
    const QJsonObject index{{QStringLiteral("format"), indexFormatName()},
                            {QStringLiteral("formatVersion"), 1},
                            {QStringLiteral("toolVersion"), QStringLiteral(DRIVEDESK_VERSION)},
                            {QStringLiteral("created"), QDateTime::currentDateTimeUtc().toString(Qt::ISODate)},
                            {QStringLiteral("family"), familyId(c.family)},
                            {QStringLiteral("link"), link},
                            {QStringLiteral("changedOnly"), m_changedOnly},
                            {QStringLiteral("drives"), drives}};
    const QString indexPath = dir.filePath(QStringLiteral("index.json"));
    QSaveFile f(indexPath);
    const QByteArray bytes = QJsonDocument(index).toJson(QJsonDocument::Indented);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size() || !f.flush() || !f.commit())
        return fail({ErrorCode::FileError, tr("backup: cannot write %1: %2").arg(indexPath, f.errorString())},
                    {{QStringLiteral("drives"), drives}}, CliExit::DriveFailed);

    const QJsonObject json{{QStringLiteral("folder"), m_dir},
                           {QStringLiteral("index"), indexPath},
                           {QStringLiteral("changedOnly"), m_changedOnly},
                           {QStringLiteral("drives"), drives}};
    QString text = CliDescribe::table(rows);
    text += tr("%1 of %n drive(s) saved to %2 (index: %3).", nullptr, int(m_transfer->results().size()))
                .arg(saved)
                .arg(m_dir, indexPath);
    conclude(json, text);
}

} // namespace dd
