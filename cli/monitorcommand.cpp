#include "cli/monitorcommand.h"

#include "cli/clidescribe.h"
#include "cli/clivalues.h"

#include "core/drive/drive.h"
#include "core/trend/channelsampler.h"
#include "core/trend/linkrate.h"
#include "core/trend/trendchannel.h"

#include <QFile>
#include <QFileInfo>

#include <QJsonArray>
#include <cmath>

namespace dd {

MonitorCommand::MonitorCommand(CliContext *c)
    : CliCommand(QStringLiteral("monitor"), c)
    , m_duration(this)
{
    m_duration.setSingleShot(true);
    m_duration.setTimerType(Qt::PreciseTimer);
    connect(&m_duration, &QTimer::timeout, this, [this] { end({}); });
}

bool MonitorCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 1, -1,
                         tr("a comma-separated list of channels, e.g. speed,torque "
                            "(see the channels command)"),
                         error))
        return false;
    for (const QString &arg : inv.positionals) {
        for (const QString &id : arg.split(QLatin1Char(','))) {
            const QString t = id.trimmed();
            if (t.isEmpty()) {
                *error = tr("monitor: empty channel name in \"%1\".").arg(arg);
                return false;
            }
            if (!m_channelIds.contains(t))
                m_channelIds << t;
        }
    }
    if (inv.has(QStringLiteral("rate"))) {
        const auto v = CliValues::real(inv.value(QStringLiteral("rate")), 0.01, 1000, QStringLiteral("--rate"), error);
        if (!v)
            return false;
        m_rateHz = *v;
    }
    if (inv.has(QStringLiteral("duration"))) {
        const auto v = CliValues::real(inv.value(QStringLiteral("duration")), 0.001, 31 * 86400.0,
                                       QStringLiteral("--duration"), error);
        if (!v)
            return false;
        m_durationS = *v;
    }
    if (inv.has(QStringLiteral("output"))) {
        m_csvPath = inv.value(QStringLiteral("output"));
        // Try it now: an unwritable path is bad input, found before anything is sent. The
        // header (the drive's channels and units) is written once the link is open.
        QFile probe(m_csvPath);
        if (m_csvPath.isEmpty() || QFileInfo(m_csvPath).isDir()
            || !probe.open(QIODevice::WriteOnly | QIODevice::Append)) {
            *error = tr("Cannot write %1: %2. Check the folder exists and is writable.")
                         .arg(m_csvPath, probe.errorString());
            return false;
        }
    }
    return true;
}

void MonitorCommand::start()
{
    Drive *d = drive();
    const QList<ChannelInfo> offered = d->channels();
    QStringList unknown;
    for (const QString &id : m_channelIds) {
        auto it = std::find_if(offered.begin(), offered.end(), [&](const ChannelInfo &c) { return c.id == id; });
        if (it == offered.end())
            unknown << id;
        else
            m_channels << *it;
    }
    if (!unknown.isEmpty()) {
        QStringList ids;
        for (const ChannelInfo &c : offered)
            ids << c.id;
        return fail({ErrorCode::InvalidArgument,
                     tr("This drive has no channel %1. Its channels: %2.")
                         .arg(unknown.join(QLatin1String(", ")), ids.join(QLatin1String(", ")))});
    }
    if (!m_csvPath.isEmpty()) {
        if (Error e = m_csv.open(m_csvPath, TrendChannel::fromInfos(m_channels), 0))
            return fail(e);
    }

    if (m_rateHz <= 0.0)
        m_rateHz = LinkRate::forReadUs(d->channelReadUs(m_channelIds));
    m_sampler = new ChannelSampler(d, this);
    m_sampler->setChannels(m_channelIds);
    m_sampler->setIntervalMs(qMax(1, int(std::lround(1000.0 / m_rateHz))));
    connect(m_sampler, &ChannelSampler::sampled, this, &MonitorCommand::onSample);
    connect(m_sampler, &ChannelSampler::failed, this, &MonitorCommand::end);

    if (!m_csv.isOpen() && !out()->isJson()) {
        QStringList head{tr("time [s]")};
        for (const ChannelInfo &c : m_channels)
            head << (c.unit.isEmpty() ? c.id : QStringLiteral("%1 [%2]").arg(c.id, c.unit));
        // Each column as wide as its header (at least 14), so values stay under it.
        m_columnWidths.clear();
        for (int i = 0; i < head.size(); ++i)
            m_columnWidths << qMax(i == 0 ? 10 : 14, CliDescribe::displayWidth(head.at(i)) + 1);
        out()->line(textRow(head));
    }
    if (m_durationS > 0)
        m_duration.start(int(std::lround(m_durationS * 1000)));
    m_sampler->start();
}

QString MonitorCommand::textRow(const QStringList &cells) const
{
    QString row;
    for (int i = 0; i < cells.size(); ++i) {
        const int width = i < m_columnWidths.size() ? m_columnWidths.at(i) : (i == 0 ? 10 : 14);
        // A value wider than its column still gets a space before it.
        row += CliDescribe::padLeft(cells.at(i), qMax(width, CliDescribe::displayWidth(cells.at(i)) + 1));
    }
    return row;
}

void MonitorCommand::onSample(double timeS, const QMap<QString, double> &values)
{
    if (m_csv.isOpen()) {
        if (Error e = m_csv.writeRowAtSeconds(timeS, values))
            end(e);
        return;
    }
    if (out()->isJson()) {
        QJsonObject o{{QStringLiteral("time"), std::round(timeS * 1e6) / 1e6}};
        for (const ChannelInfo &c : m_channels)
            if (values.contains(c.id))
                o.insert(c.id, values.value(c.id));
        out()->jsonLine(o);
        return;
    }
    QStringList cells{QString::number(timeS, 'f', 3)};
    for (const ChannelInfo &c : m_channels)
        cells << (values.contains(c.id) ? QString::number(values.value(c.id), 'f', qBound(0, c.decimals, 9))
                                        : QStringLiteral("-"));
    out()->line(textRow(cells));
}

void MonitorCommand::interrupt(int)
{
    end({}); // Ctrl-C is the normal end of an open-ended monitor
}

void MonitorCommand::end(const Error &error)
{
    if (isDone())
        return;
    m_duration.stop();
    if (m_sampler)
        m_sampler->stop();
    const quint64 samples = m_sampler ? m_sampler->sampleCount() : 0;
    const quint64 skipped = m_sampler ? m_sampler->skippedCount() : 0;
    Error e = error;
    if (m_csv.isOpen()) {
        const Error ce = m_csv.close();
        if (!e)
            e = ce;
    }
    QJsonObject summary{{QStringLiteral("samples"), double(samples)},
                        {QStringLiteral("skipped"), double(skipped)},
                        {QStringLiteral("rateHz"), m_rateHz}};
    if (!m_csvPath.isEmpty())
        summary.insert(QStringLiteral("file"), m_csvPath);
    if (e)
        return fail(e, summary);
    if (skipped > 0)
        out()->note(tr("%1 ticks were skipped because the link was slower than %2 Hz; "
                       "lower --rate or sample fewer channels.")
                        .arg(skipped)
                        .arg(m_rateHz));
    if (m_csvPath.isEmpty()) {
        // The samples were the output; in JSON mode end with a summary line.
        if (out()->isJson()) {
            summary.insert(QStringLiteral("command"), name());
            summary.insert(QStringLiteral("ok"), true);
            out()->jsonLine(summary);
        }
        return finish(CliExit::Ok);
    }
    succeed(summary, tr("%1 samples written to %2.").arg(samples).arg(m_csvPath));
}

} // namespace dd
