#include "core/report/journalkey.h"

#include "core/drive/drivetypes.h"

#include <QCryptographicHash>
#include <QJsonDocument>
#include <QStringList>

namespace dd {

JournalKey JournalKey::of(const DriveIdentity &identity, const QString &link, const QString &machine)
{
    JournalKey k;
    k.machine = machine.trimmed();
    k.family = identity.family;
    k.address = identity.address;
    k.link = link.trimmed();
    k.firmware = identity.firmware.trimmed();
    k.model = identity.model.trimmed();
    return k;
}

QJsonObject JournalKey::toJson() const
{
    return {{QStringLiteral("machine"), machine},   {QStringLiteral("family"), familyId(family)},
            {QStringLiteral("address"), address},   {QStringLiteral("link"), link},
            {QStringLiteral("firmware"), firmware}, {QStringLiteral("model"), model}};
}

JournalKey JournalKey::fromJson(const QJsonObject &json)
{
    JournalKey k;
    k.machine = json.value(QStringLiteral("machine")).toString();
    k.family = familyFromId(json.value(QStringLiteral("family")).toString()).value_or(Family::ServoModbus);
    k.address = json.value(QStringLiteral("address")).toInt(-1);
    k.link = json.value(QStringLiteral("link")).toString();
    k.firmware = json.value(QStringLiteral("firmware")).toString();
    k.model = json.value(QStringLiteral("model")).toString();
    return k;
}

bool JournalKey::operator==(const JournalKey &o) const
{
    return machine == o.machine && family == o.family && address == o.address && link == o.link
        && firmware == o.firmware && model == o.model;
}

QString JournalKey::fileName() const
{
    // QJsonDocument sorts the keys: the same key always gives the same bytes.
    const QByteArray canonical = QJsonDocument(toJson()).toJson(QJsonDocument::Compact);
    const QByteArray digest = QCryptographicHash::hash(canonical, QCryptographicHash::Sha256).toHex().left(16);
    return QStringLiteral("%1-%2-%3.json").arg(familyId(family)).arg(address).arg(QString::fromLatin1(digest));
}

QString JournalKey::identifiedBy() const
{
    QStringList parts;
    if (!machine.isEmpty())
        parts << tr("machine “%1”").arg(machine);
    parts << tr("%1 address %2 on %3")
                 .arg(familyId(family))
                 .arg(address)
                 .arg(link.isEmpty() ? tr("an unnamed link") : link);
    if (!firmware.isEmpty())
        parts << tr("firmware %1").arg(firmware);
    if (!model.isEmpty())
        parts << tr("model %1").arg(model);
    return tr("Identified by %1.").arg(parts.join(QLatin1String(", ")));
}

QString JournalKey::cannotTellApart() const
{
    QStringList same{tr("link"), tr("address")};
    if (!firmware.isEmpty())
        same << tr("firmware");
    if (!model.isEmpty())
        same << tr("model");
    const QString last = same.takeLast();
    QString text = tr("This family reports no serial number: two drives with the same %1 cannot be told apart.")
                       .arg(tr("%1 and %2").arg(same.join(QLatin1String(", ")), last));
    if (firmware.isEmpty())
        text += QLatin1Char(' ') + tr("The drive reported no firmware version.");
    if (machine.isEmpty())
        text += QLatin1Char(' ')
            + tr("No machine name was set: drives of different machines reached the same way share one journal.");
    return text;
}

} // namespace dd
