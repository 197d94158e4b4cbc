#include "ui/bus/connectrequest.h"

#include "core/protocol/familytraits.h"

#include <QCanBus>
#include <QCoreApplication>
#include <QSettings>

namespace dd {

QList<ConnectionSettings> ConnectRequest::attempts() const
{
    if (!detect)
        return {settings};
    const LinkKind link = settings.isCan() ? LinkKind::Can : LinkKind::Serial;
    QList<ConnectionSettings> out;
    for (const FamilyTraits *traits : allFamilyTraits()) {
        for (const FramingTraits &f : traits->framings) {
            if (f.link != link || !f.detect)
                continue;
            ConnectionSettings s = settings;
            s.family = traits->family;
            // A family with a single framing keeps the default (empty).
            s.framing = traits->framings.size() > 1 ? f.id : QString();
            out.append(s);
        }
    }
    return out;
}

ScanOptions ConnectRequest::scanOptionsFor(const ConnectionSettings &attempt) const
{
    ScanOptions o = scanOptions;
    const FamilyTraits &traits = familyTraits(attempt.family);
    if (const FramingTraits *f = traits.framingFor(attempt.isCan() ? LinkKind::Can : LinkKind::Serial,
                                                   attempt.framing)) {
        o.from = qMax(o.from, f->addresses.first);
        o.to = qMin(o.to, f->addresses.last);
    }
    o.bauds = sweepBauds && !attempt.isCan() ? traits.scanBauds : QList<int>();
    return o;
}

bool ConnectRequest::fromCommandLine(const QString &link, const QString &family, int baud, int bitrate,
                                     const QString &framing, ConnectRequest *out, QString *error)
{
    ConnectRequest r;
    r.detect = family.isEmpty() || family == QLatin1String("detect");
    if (!r.detect) {
        const std::optional<Family> f = familyFromId(family);
        if (!f) {
            if (error)
                *error = QCoreApplication::translate("dd::ConnectRequest",
                                                     "Unknown family \"%1\"; use one of: %2, detect.")
                             .arg(family, familyIds().join(QStringLiteral(", ")));
            return false;
        }
        r.settings.family = *f;
    }
    const QStringList framings = allFramingIds();
    if (!framing.isEmpty() && !framings.contains(framing)) {
        if (error)
            *error = QCoreApplication::translate("dd::ConnectRequest", "Unknown framing \"%1\"; use one of: %2.")
                         .arg(framing, framings.join(QStringLiteral(", ")));
        return false;
    }
    const QString plugin = link.section(QLatin1Char(':'), 0, 0);
    if (link.contains(QLatin1Char(':')) && QCanBus::instance()->plugins().contains(plugin))
        r.settings.can = link;
    else
        r.settings.port = link;
    r.settings.baud = baud;
    r.settings.bitrate = bitrate;
    r.settings.framing = framing;
    r.scan = true;
    *out = r;
    return true;
}

void ConnectRequest::save(QSettings &s) const
{
    s.beginGroup(QStringLiteral("connect"));
    s.setValue(QStringLiteral("family"), detect ? QStringLiteral("detect") : familyId(settings.family));
    s.setValue(QStringLiteral("port"), settings.port);
    s.setValue(QStringLiteral("can"), settings.can);
    s.setValue(QStringLiteral("baud"), settings.baud);
    s.setValue(QStringLiteral("bitrate"), settings.bitrate);
    s.setValue(QStringLiteral("framing"), settings.framing);
    s.setValue(QStringLiteral("scan"), scan);
    s.setValue(QStringLiteral("scanFrom"), scanOptions.from);
    s.setValue(QStringLiteral("scanTo"), scanOptions.to);
    s.setValue(QStringLiteral("sweepBauds"), sweepBauds);
    s.setValue(QStringLiteral("probeTimeoutMs"), scanOptions.timeoutMs);
    s.endGroup();
}

ConnectRequest ConnectRequest::load(QSettings &s)
{
    ConnectRequest r;
    s.beginGroup(QStringLiteral("connect"));
    const QString family = s.value(QStringLiteral("family"), QStringLiteral("detect")).toString();
    r.detect = family == QLatin1String("detect");
    r.settings.family = familyFromId(family).value_or(Family::ServoModbus);
    r.settings.port = s.value(QStringLiteral("port")).toString();
    r.settings.can = s.value(QStringLiteral("can")).toString();
    r.settings.baud = s.value(QStringLiteral("baud"), 0).toInt();
    r.settings.bitrate = s.value(QStringLiteral("bitrate"), 0).toInt();
    r.settings.framing = s.value(QStringLiteral("framing")).toString();
    r.scan = s.value(QStringLiteral("scan"), true).toBool();
    r.scanOptions.from = qBound(0, s.value(QStringLiteral("scanFrom"), DefaultFrom).toInt(), 255);
    r.scanOptions.to = qBound(r.scanOptions.from, s.value(QStringLiteral("scanTo"), DefaultTo).toInt(), 255);
    r.scanOptions.timeoutMs = qBound(-1, s.value(QStringLiteral("probeTimeoutMs"), DefaultProbeTimeoutMs).toInt(),
                                     5000);
    r.sweepBauds = s.value(QStringLiteral("sweepBauds"), false).toBool();
    s.endGroup();
    return r;
}

QString ConnectRequest::describe() const
{
    const QString family = detect ? QCoreApplication::translate("dd::ConnectRequest", "auto-detect")
                                  : familyId(settings.family);
    QString link = settings.linkName();
    if (!settings.isCan() && settings.baud > 0)
        link += QStringLiteral(" @ %1").arg(settings.baud);
    if (settings.isCan() && settings.bitrate > 0)
        link += QStringLiteral(" @ %1 kbit/s").arg(settings.bitrate / 1000);
    return QCoreApplication::translate("dd::ConnectRequest", "%1 on %2").arg(family, link);
}

} // namespace dd
