#include "cli/fleetcommand.h"

#include "cli/clivalues.h"

#include "core/drive/drive.h"
#include "core/drive/driveconnection.h"
#include "core/drive/familybackend.h" // driveconnection.h needs it complete (QPointer)
#include "core/fleet/fleettransfer.h"

namespace dd {

bool FleetCommand::prepareTargets(const CliInvocation &inv, QString *error)
{
    const CliGlobals &g = context()->globals;
    m_all = inv.has(QStringLiteral("all"));
    if (m_all && g.addressGiven) {
        *error = tr("%1: give either --all or --address, not both.").arg(name());
        return false;
    }
    if (!m_all && (inv.has(QStringLiteral("from")) || inv.has(QStringLiteral("to")))) {
        *error = tr("%1: --from and --to narrow the scan of --all.").arg(name());
        return false;
    }
    m_addresses = g.addresses;
    if (!m_all)
        return true;
    const AddressRange range = g.addressRange();
    m_scan.from = range.first;
    m_scan.to = range.last;
    for (const char *o : {"from", "to"}) {
        const QString option = QString::fromLatin1(o);
        if (!inv.has(option))
            continue;
        const auto v = CliValues::integer(inv.value(option), range.first, range.last, QStringLiteral("--") + option,
                                          error);
        if (!v)
            return false;
        (option == QLatin1String("from") ? m_scan.from : m_scan.to) = int(*v);
    }
    if (m_scan.from > m_scan.to) {
        *error = tr("%1: --from %2 is above --to %3.").arg(name()).arg(m_scan.from).arg(m_scan.to);
        return false;
    }
    if (g.connection.timeoutMs > 0)
        m_scan.timeoutMs = g.connection.timeoutMs;
    return true;
}

void FleetCommand::start()
{
    if (m_all)
        return scan();
    run(m_addresses);
}

void FleetCommand::scan()
{
    m_discovery = context()->connection->createDiscovery(m_scan);
    if (!m_discovery)
        return fail({ErrorCode::NotSupported, tr("This family cannot scan; name the drives with --address.")});
    out()->note(tr("Scanning addresses %1 to %2 ...").arg(m_scan.from).arg(m_scan.to));
    connect(m_discovery, &Discovery::finished, this, [this](const Error &error) {
        QList<int> found;
        for (const DiscoveredDrive &d : m_discovery->results())
            if (d.address >= m_scan.from && d.address <= m_scan.to && !found.contains(d.address))
                found << d.address;
        std::sort(found.begin(), found.end());
        if (m_interrupted)
            return fail({ErrorCode::Cancelled, tr("Interrupted during the scan; nothing was done.")});
        if (error && found.isEmpty())
            return fail(error);
        if (found.isEmpty())
            return fail({ErrorCode::Timeout,
                         tr("No drive answered the scan of addresses %1 to %2.").arg(m_scan.from).arg(m_scan.to)});
        QStringList list;
        for (int a : std::as_const(found))
            list << QString::number(a);
        out()->note(tr("Found %n drive(s): %1.", nullptr, int(found.size())).arg(list.join(QLatin1String(", "))));
        run(found);
    });
    m_discovery->start();
}

FleetTransfer *FleetCommand::newTransfer(const QList<int> &addresses)
{
    QList<Drive *> drives;
    for (int a : addresses) {
        Drive *d = context()->connection->drive(a);
        if (d && context()->dictionary && d->dictionary() != context()->dictionary)
            d->setDictionary(context()->dictionary);
        drives << d;
    }
    m_transfer = new FleetTransfer(drives, this);
    return m_transfer;
}

void FleetCommand::interrupt(int)
{
    m_interrupted = true;
    if (m_discovery && !m_transfer)
        m_discovery->cancel();
    if (m_transfer) {
        out()->note(tr("Finishing the drives under way so that their reports are complete; no further "
                       "drive is started."));
        m_transfer->cancel();
    }
}

void FleetCommand::linkLost(const Error &why)
{
    if (!m_transfer || !m_transfer->isRunning())
        return CliCommand::linkLost(why);
    Error e = why;
    if (e.message.isEmpty())
        e.message = tr("The link was lost. Check the adapter and its cable.");
    if (e.code == ErrorCode::None)
        e.code = ErrorCode::LinkClosed;
    out()->note(e.message);
    m_transfer->abort(e);
}

CliExit FleetCommand::exitOf(const FleetDriveResult &r) const
{
    switch (r.state) {
    case FleetDriveResult::State::Done: return CliExit::Ok;
    case FleetDriveResult::State::Failed: return CliCommand::exitForFailure(r.error);
    default: return CliExit::DriveFailed;
    }
}

CliExit FleetCommand::worstExit() const
{
    CliExit worst = CliExit::Ok;
    for (const FleetDriveResult &r : m_transfer->results())
        worst = std::max(worst, exitOf(r));
    return worst;
}

QJsonObject FleetCommand::driveJson(const FleetDriveResult &r) const
{
    QJsonObject o{{QStringLiteral("address"), r.address},
                  {QStringLiteral("result"), FleetDriveResult::stateId(r.state)},
                  {QStringLiteral("exitCode"), int(exitOf(r))}};
    if (!r.identity.firmware.isEmpty())
        o.insert(QStringLiteral("firmware"), r.identity.firmware);
    if (!r.identity.model.isEmpty())
        o.insert(QStringLiteral("model"), r.identity.model);
    if (r.error)
        o.insert(QStringLiteral("error"), CliOutput::errorJson(r.error));
    if (r.state == FleetDriveResult::State::Failed)
        o.insert(QStringLiteral("stoppedAt"), r.stoppedAt);
    return o;
}

QString FleetCommand::failureLine(const FleetDriveResult &r) const
{
    if (r.state == FleetDriveResult::State::NotAttempted)
        return r.error ? tr("drive %1: not attempted (%2)").arg(r.address).arg(r.error.message)
                       : tr("drive %1: not attempted").arg(r.address);
    QString stage;
    if (r.stoppedAt == QLatin1String("identify"))
        stage = tr("while identifying it");
    else if (r.stoppedAt == QLatin1String("read"))
        stage = tr("while reading its parameters");
    else if (r.stoppedAt == QLatin1String("write"))
        stage = tr("while writing");
    else
        stage = tr("before it started");
    return tr("drive %1: FAILED %2: %3").arg(r.address).arg(stage, r.error.message);
}

void FleetCommand::conclude(const QJsonObject &json, const QString &text)
{
    const CliExit worst = worstExit();
    if (worst == CliExit::Ok)
        return succeed(json, text);
    if (!out()->isJson())
        out()->line(text);
    QStringList bad;
    ErrorCode code = ErrorCode::VerifyMismatch;
    for (const FleetDriveResult &r : m_transfer->results()) {
        if (exitOf(r) == CliExit::Ok)
            continue;
        if (bad.isEmpty() && r.error)
            code = r.error.code;
        bad << QString::number(r.address);
    }
    fail({code,
          tr("%n of %1 drive(s) did not complete: %2.", nullptr, int(bad.size()))
              .arg(m_transfer->results().size())
              .arg(bad.join(QLatin1String(", ")))},
         json, worst);
}

} // namespace dd
