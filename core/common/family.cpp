#include "core/common/family.h"

#include <QList>

namespace dd {

namespace {

struct FamilyName
{
    Family family;
    const char *id;
};

// The ids of the families, one line per family (the family table, with each family's
// traits, is core/protocol/familytraits.cpp).
const QList<FamilyName> &names()
{
    static const QList<FamilyName> table{
        {Family::ServoCan, "servo-can"},
        {Family::ServoModbus, "servo-modbus"},
        {Family::Shuoke, "shuoke"},
    };
    return table;
}

} // namespace

QString familyId(Family family)
{
    for (const FamilyName &n : names())
        if (n.family == family)
            return QString::fromLatin1(n.id);
    return {};
}

std::optional<Family> familyFromId(const QString &id)
{
    const QString key = id.trimmed().toLower();
    for (const FamilyName &n : names())
        if (key == QLatin1String(n.id))
            return n.family;
    return std::nullopt;
}

QList<Family> allFamilies()
{
    QList<Family> out;
    for (const FamilyName &n : names())
        out << n.family;
    return out;
}

QStringList familyIds()
{
    QStringList out;
    for (const FamilyName &n : names())
        out << QString::fromLatin1(n.id);
    return out;
}

} // namespace dd
