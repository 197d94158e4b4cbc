#include "cli/pingcommand.h"

#include "cli/clidescribe.h"
#include "cli/clivalues.h"
#include "core/drive/drive.h"
#include "core/drive/driveconnection.h"
#include "core/link/traffictap.h"

#include <QJsonObject>

namespace dd {

bool PingCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 0, 0, QString(), error))
        return false;
    if (inv.has(QStringLiteral("count"))) {
        const auto v = CliValues::integer(inv.value(QStringLiteral("count")), 1, 100000, QStringLiteral("--count"),
                                          error);
        if (!v)
            return false;
        m_count = int(*v);
    }
    return true;
}

void PingCommand::start()
{
    const ConnectionSettings &s = context()->connection->settings();
    m_health = LinkHealth(s.isCan() ? 0 : s.baud);
    m_health.setAddress(drive()->address());
    connect(context()->connection->tap(), &TrafficTap::frameRecorded, this,
            [this](const TrafficRecord &r) { m_health.add(r); });
    next();
}

void PingCommand::next()
{
    if (m_sent >= m_count)
        return report();
    ++m_sent;
    onFinished(drive()->readStatus(), [this](DriveReply *r) {
        if (!r->ok()) {
            ++m_failed;
            m_lastError = r->error();
            if (m_lastError.code == ErrorCode::LinkClosed || m_lastError.code == ErrorCode::Cancelled)
                return fail(m_lastError);
        }
        next();
    });
}

void PingCommand::report()
{
    m_health.closeOutstanding(); // every ping has finished: a request still out timed out
    const LinkHealth::Summary h = m_health.summary();
    const int answered = m_count - m_failed;
    QJsonObject json{
        {QStringLiteral("address"), drive()->address()},
        {QStringLiteral("link"), context()->connection->settings().linkName()},
        {QStringLiteral("count"), m_count},
        {QStringLiteral("answered"), answered},
        {QStringLiteral("requests"), h.requests},
        {QStringLiteral("turnaroundMs"),
         QJsonObject{{QStringLiteral("min"), h.minMs},
                     {QStringLiteral("median"), h.medianMs},
                     {QStringLiteral("max"), h.maxMs}}},
        {QStringLiteral("timeouts"), h.timeouts},
        {QStringLiteral("checksumErrors"), h.checksumErrors},
        {QStringLiteral("lateReplies"), h.lateReplies},
        {QStringLiteral("retries"), h.retries},
        {QStringLiteral("busyLineSends"), h.busyLineSends},
        {QStringLiteral("recommendedTimeoutMs"), h.recommendedTimeoutMs},
        {QStringLiteral("recommendedGapMs"), h.recommendedGapMs},
    };
    if (answered == 0) {
        Error e{ErrorCode::Timeout,
                tr("The drive at address %1 answered none of %2 requests. Last error: %3")
                    .arg(drive()->address())
                    .arg(m_count)
                    .arg(m_lastError.message)};
        return fail(e, json);
    }
    auto ms = [](double v) { return QString::number(v, 'f', 2); };
    const QList<QPair<QString, QString>> rows{
        {tr("Answered"), tr("%1 of %2 (%3 requests on the wire)").arg(answered).arg(m_count).arg(h.requests)},
        {tr("Turnaround"), tr("min %1 ms, median %2 ms, max %3 ms").arg(ms(h.minMs), ms(h.medianMs), ms(h.maxMs))},
        {tr("Timeouts"), QString::number(h.timeouts)},
        {tr("Checksum errors"), QString::number(h.checksumErrors)},
        {tr("Late or duplicated replies"), QString::number(h.lateReplies)},
        {tr("Retries"), QString::number(h.retries)},
        {tr("Sent on a busy line"),
         h.busyLineSends ? tr("%1 (the line was never quiet: is another master on the bus, or a drive sending on "
                              "its own?)")
                               .arg(h.busyLineSends)
                         : QStringLiteral("0")},
        {tr("Recommended timeout"),
         tr("--timeout %1 (reply allowance beyond the wire time, ms)").arg(h.recommendedTimeoutMs)},
        {tr("Recommended gap"), tr("%1 ms between requests").arg(h.recommendedGapMs)},
    };
    succeed(json, CliDescribe::table(rows));
}

} // namespace dd
