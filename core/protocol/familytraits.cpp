#include "core/protocol/familytraits.h"

#include "core/protocol/framedescriber.h"

#include <QCoreApplication>

namespace dd {

QString FramingTraits::displayName() const
{
    return QCoreApplication::translate("dd::FamilyTraits", name);
}

QString FamilyTraits::displayName() const
{
    return QCoreApplication::translate("dd::FamilyTraits", name);
}

QString FamilyTraits::speedUnitText() const
{
    return QCoreApplication::translate("dd::FamilyTraits", speedUnit);
}

QString FamilyTraits::positionUnitText() const
{
    return QCoreApplication::translate("dd::FamilyTraits", positionUnit);
}

bool FamilyTraits::talks(LinkKind link) const
{
    return defaultFraming(link) != nullptr;
}

const FramingTraits *FamilyTraits::framing(const QString &id) const
{
    for (const FramingTraits &f : framings)
        if (f.id == id)
            return &f;
    return nullptr;
}

const FramingTraits *FamilyTraits::defaultFraming(LinkKind link) const
{
    for (const FramingTraits &f : framings)
        if (f.link == link)
            return &f;
    return nullptr;
}

const FramingTraits *FamilyTraits::framingFor(LinkKind link, const QString &id) const
{
    if (id.isEmpty())
        return defaultFraming(link);
    const FramingTraits *f = framing(id);
    return f && f->link == link ? f : nullptr;
}

QStringList FamilyTraits::framingIds(LinkKind link) const
{
    QStringList out;
    for (const FramingTraits &f : framings)
        if (f.link == link)
            out << f.id;
    return out;
}

AddressRange FamilyTraits::addresses(LinkKind link) const
{
    AddressRange out{-1, -1};
    for (const FramingTraits &f : framings) {
        if (f.link != link)
            continue;
        out.first = out.first < 0 ? f.addresses.first : qMin(out.first, f.addresses.first);
        out.last = qMax(out.last, f.addresses.last);
    }
    return out;
}

// Each family's traits, defined in its own folder (core/protocol/<family>/<family>traits.cpp).
namespace servocan {
const FamilyTraits &traits();
}
namespace servomodbus {
const FamilyTraits &traits();
}
namespace shuoke {
const FamilyTraits &traits();
}

QList<const FamilyTraits *> allFamilyTraits()
{
    // The family table: one line per family, in auto-detect order.
    static const QList<const FamilyTraits *> table{
        &servocan::traits(),
        &servomodbus::traits(),
        &shuoke::traits(),
    };
    return table;
}

const FamilyTraits &familyTraits(Family family)
{
    for (const FamilyTraits *t : allFamilyTraits())
        if (t->family == family)
            return *t;
    qFatal("familyTraits: family %d is not in the family table", int(family));
}

QStringList allFramingIds()
{
    QStringList out;
    for (const FamilyTraits *t : allFamilyTraits())
        for (const FramingTraits &f : t->framings)
            if (!out.contains(f.id))
                out << f.id;
    return out;
}

std::unique_ptr<FrameDescriber> createFrameDescriber(Family family, const QString &framing, const QVariantMap &options)
{
    return familyTraits(family).describer(framing, options);
}

} // namespace dd
