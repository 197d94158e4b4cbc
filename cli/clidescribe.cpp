#include "cli/clidescribe.h"

#include "core/params/parameterdictionary.h"
#include "core/tuning/stepmetrics.h"

namespace dd {

QJsonObject CliDescribe::identity(const DriveIdentity &id)
{
    return {{QStringLiteral("family"), familyId(id.family)},
            {QStringLiteral("address"), id.address},
            {QStringLiteral("firmware"), id.firmware},
            {QStringLiteral("model"), id.model},
            {QStringLiteral("link"), id.link}};
}

QJsonObject CliDescribe::status(const DriveStatus &s)
{
    QJsonObject o{{QStringLiteral("online"), s.online},
                  {QStringLiteral("running"), s.running},
                  {QStringLiteral("enabled"), s.enabled},
                  {QStringLiteral("alarm"), s.alarmCode}};
    if (s.positionValid)
        o.insert(QStringLiteral("position"), double(s.position));
    return o;
}

QString CliDescribe::statusText(const DriveStatus &s)
{
    QStringList parts;
    parts << (s.online ? tr("online") : tr("offline"));
    parts << (s.enabled ? tr("enabled") : tr("disabled"));
    parts << (s.running ? tr("running") : tr("idle"));
    if (s.alarmCode)
        parts << tr("alarm %1").arg(s.alarmCode);
    return parts.join(tr(", ", "separator of the state words: online, enabled, idle"));
}

QJsonArray CliDescribe::channels(const QList<ChannelInfo> &channels)
{
    QJsonArray a;
    for (const ChannelInfo &c : channels)
        a.append(QJsonObject{{QStringLiteral("id"), c.id},
                             {QStringLiteral("name"), c.name},
                             {QStringLiteral("unit"), c.unit},
                             {QStringLiteral("decimals"), c.decimals}});
    return a;
}

QJsonObject CliDescribe::discovered(const DiscoveredDrive &d)
{
    QJsonObject o{{QStringLiteral("family"), familyId(d.family)},
                  {QStringLiteral("address"), d.address},
                  {QStringLiteral("firmware"), d.firmware},
                  {QStringLiteral("state"), d.state},
                  {QStringLiteral("link"), d.link}};
    if (d.baud)
        o.insert(QStringLiteral("baud"), d.baud);
    if (d.bitrate)
        o.insert(QStringLiteral("bitrate"), d.bitrate);
    if (!d.framing.isEmpty())
        o.insert(QStringLiteral("framing"), d.framing);
    return o;
}

QString CliDescribe::discoveredText(const DiscoveredDrive &d)
{
    const QString speed = d.baud ? tr("%1 baud").arg(d.baud) : d.bitrate ? tr("%1 bit/s").arg(d.bitrate) : QString();
    QStringList cols{familyId(d.family), tr("address %1").arg(d.address)};
    if (!speed.isEmpty())
        cols << speed;
    if (!d.framing.isEmpty())
        cols << d.framing;
    cols << (d.firmware.isEmpty() ? tr("firmware ?") : tr("firmware %1").arg(d.firmware));
    if (!d.state.isEmpty())
        cols << d.state;
    return cols.join(QLatin1String("  "));
}

QJsonObject CliDescribe::parameter(const ParameterDictionary &dict, int index, std::optional<qint64> value)
{
    const ParameterInfo *p = dict.byIndex(index);
    QJsonObject o{{QStringLiteral("index"), index},
                  {QStringLiteral("key"), p ? p->key : QStringLiteral("P%1").arg(index)},
                  {QStringLiteral("name"), dict.displayName(index)},
                  {QStringLiteral("unit"), p ? p->unit : QString()}};
    if (value)
        o.insert(QStringLiteral("value"), double(*value));
    return o;
}

QString CliDescribe::table(const QList<QPair<QString, QString>> &rows)
{
    int width = 0;
    for (const auto &r : rows)
        width = qMax(width, displayWidth(r.first));
    QString out;
    for (const auto &r : rows)
        out += padRight(r.first, width + 2) + r.second + QLatin1Char('\n');
    return out;
}

int CliDescribe::displayWidth(const QString &text)
{
    int width = 0;
    for (const char32_t c : text.toUcs4()) {
        const bool wide = (c >= 0x1100 && c <= 0x115F) || (c >= 0x2E80 && c <= 0x303E) || (c >= 0x3041 && c <= 0x33FF)
            || (c >= 0x3400 && c <= 0x4DBF) || (c >= 0x4E00 && c <= 0x9FFF) || (c >= 0xA000 && c <= 0xA4CF)
            || (c >= 0xAC00 && c <= 0xD7A3) || (c >= 0xF900 && c <= 0xFAFF) || (c >= 0xFE30 && c <= 0xFE4F)
            || (c >= 0xFF00 && c <= 0xFF60) || (c >= 0xFFE0 && c <= 0xFFE6) || (c >= 0x20000 && c <= 0x3FFFD);
        width += wide ? 2 : 1;
    }
    return width;
}

QString CliDescribe::padRight(const QString &text, int width)
{
    return text + QString(qMax(0, width - displayWidth(text)), QLatin1Char(' '));
}

QString CliDescribe::padLeft(const QString &text, int width)
{
    return QString(qMax(0, width - displayWidth(text)), QLatin1Char(' ')) + text;
}

QString CliDescribe::metric(const Metric &m, const QString &key, int msDecimals)
{
    if (!m.value)
        return QStringLiteral("—");
    const double v = *m.value;
    if (key == QLatin1String("overshoot"))
        return QStringLiteral("%1 %").arg(v, 0, 'f', 1);
    if (key.startsWith(QLatin1String("rise")) || key.startsWith(QLatin1String("settling"))
        || key == QLatin1String("sampleInterval"))
        return QStringLiteral("%1 ms").arg(v * 1000.0, 0, 'f', msDecimals);
    return QString::number(v, 'g', 4);
}

} // namespace dd
