#include "cli/scancommand.h"

#include "cli/clidescribe.h"
#include "cli/clivalues.h"

#include "core/drive/driveconnection.h"
#include "core/drive/familybackend.h" // driveconnection.h needs it complete (QPointer)
#include "core/protocol/familytraits.h"

namespace dd {

bool ScanCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 0, 0, QString(), error))
        return false;
    const ConnectionSettings &c = context()->globals.connection;
    const bool can = context()->globals.isCanLink();
    const AddressRange range = context()->globals.addressRange();
    const int lo = range.first, hi = range.last;
    m_options.from = lo;
    m_options.to = hi;
    if (inv.has(QStringLiteral("from"))) {
        const auto v = CliValues::integer(inv.value(QStringLiteral("from")), lo, hi, QStringLiteral("--from"), error);
        if (!v)
            return false;
        m_options.from = int(*v);
    }
    if (inv.has(QStringLiteral("to"))) {
        const auto v = CliValues::integer(inv.value(QStringLiteral("to")), lo, hi, QStringLiteral("--to"), error);
        if (!v)
            return false;
        m_options.to = int(*v);
    }
    if (m_options.from > m_options.to) {
        *error = tr("scan: --from %1 is above --to %2.").arg(m_options.from).arg(m_options.to);
        return false;
    }
    if (inv.has(QStringLiteral("bauds"))) {
        if (can) {
            *error = tr("scan: --bauds is for serial links; a CAN bus runs at one bitrate (--bitrate).");
            return false;
        }
        const auto list = CliValues::integerList(inv.value(QStringLiteral("bauds")), 50, 4000000,
                                                 QStringLiteral("--bauds"), error);
        if (!list)
            return false;
        for (qint64 b : *list)
            if (!m_options.bauds.contains(int(b)))
                m_options.bauds << int(b);
    } else if (!can && c.baud == 0) {
        m_options.bauds = familyTraits(c.family).scanBauds;
    }
    if (c.timeoutMs > 0)
        m_options.timeoutMs = c.timeoutMs;
    return true;
}

void ScanCommand::start()
{
    m_discovery = context()->connection->createDiscovery(m_options);
    if (!m_discovery)
        return fail({ErrorCode::NotSupported, tr("This family cannot scan.")});
    connect(m_discovery, &Discovery::found, this, [this](const DiscoveredDrive &d) {
        // Some discoveries listen to the whole bus (servo-can heartbeats): keep to the range.
        if (d.address < m_options.from || d.address > m_options.to)
            return;
        m_found.append(CliDescribe::discovered(d));
        out()->line(CliDescribe::discoveredText(d));
    });
    connect(m_discovery, &Discovery::finished, this, &ScanCommand::onFinished);
    if (!out()->isJson()) {
        QString what = tr("Scanning addresses %1 to %2").arg(m_options.from).arg(m_options.to);
        if (!m_options.bauds.isEmpty()) {
            QStringList b;
            for (int baud : std::as_const(m_options.bauds))
                b << QString::number(baud);
            what += tr(" at %1 baud").arg(b.join(QLatin1String(", ")));
        }
        out()->note(what + QStringLiteral(" ..."));
    }
    m_discovery->start();
}

void ScanCommand::interrupt(int)
{
    m_interrupted = true;
    if (m_discovery)
        m_discovery->cancel();
}

void ScanCommand::onFinished(const Error &error)
{
    const QJsonObject json{{QStringLiteral("drives"), m_found}};
    if (error && !(error.code == ErrorCode::Cancelled && m_interrupted))
        return fail(error, json);
    if (m_found.isEmpty())
        return fail({ErrorCode::Timeout,
                     tr("No drive answered. Check the wiring (A/B or CANH/CANL swapped?), the "
                        "termination, the family (--family) and, on a serial bus, try more "
                        "baud rates with --bauds.")},
                    json);
    succeed(json,
            m_interrupted ? tr("Scan interrupted; %n drive(s) found.", nullptr, int(m_found.size()))
                          : tr("%n drive(s) found.", nullptr, int(m_found.size())));
}

} // namespace dd
