#include "common/family.h"

namespace dd {

QString familyId(Family family)
{
    switch (family) {
    case Family::ServoCan: return QStringLiteral("servo-can");
    case Family::ServoModbus: return QStringLiteral("servo-modbus");
    case Family::Shuoke: return QStringLiteral("shuoke");
    }
    return {};
}

std::optional<Family> familyFromId(const QString &id)
{
    const QString key = id.trimmed().toLower();
    for (Family f : {Family::ServoCan, Family::ServoModbus, Family::Shuoke}) {
        if (familyId(f) == key)
            return f;
    }
    return std::nullopt;
}

QStringList familyIds()
{
    return {familyId(Family::ServoCan), familyId(Family::ServoModbus), familyId(Family::Shuoke)};
}

} // namespace dd
