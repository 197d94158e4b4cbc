#include "cli/fleetrestorecommand.h"

#include "cli/backupcommands.h"
#include "cli/clidescribe.h"
#include "cli/restoredescribe.h"

#include "core/fleet/fleettransfer.h"
#include "core/params/parameterdictionary.h"

#include <QJsonArray>

namespace dd {

bool FleetRestoreCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 1, 1, tr("a backup file"), error) || !prepareTargets(inv, error))
        return false;
    m_path = inv.positionals.at(0);
    if (!FileCommand::loadFile(context(), m_path, &m_file, error))
        return false;
    m_stopOnFailure = inv.has(QStringLiteral("stop-on-failure"));
    return RestoreCommand::parseOptions(inv, m_file, m_path, *context()->dictionary, &m_options, error);
}

void FleetRestoreCommand::run(const QList<int> &addresses)
{
    newTransfer(addresses);
    m_transfer->setStopAtFirstFailure(m_stopOnFailure);
    connect(m_transfer, &FleetTransfer::finished, this, &FleetRestoreCommand::report);
    m_transfer->restore(m_file, m_options);
}

void FleetRestoreCommand::report()
{
    const ParameterDictionary &dict = *context()->dictionary;
    QJsonArray drives;
    QStringList text;
    int done = 0;
    for (const FleetDriveResult &r : m_transfer->results()) {
        QJsonObject o = driveJson(r);
        QList<QPair<QString, QString>> rows;
        o.insert(QStringLiteral("selected"), RestoreDescribe::selected(dict, r.report, &rows));
        RestoreDescribe::insertOutcomes(dict, r.report, &o);
        drives.append(o);

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
