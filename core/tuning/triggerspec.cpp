#include "core/tuning/triggerspec.h"

#include <cmath>

namespace dd {

namespace {
struct KindName
{
    TriggerSpec::Kind kind;
    const char *id;
};
constexpr KindName Kinds[] = {
    {TriggerSpec::Kind::Now, "now"},     {TriggerSpec::Kind::Rise, "rise"},
    {TriggerSpec::Kind::Fall, "fall"},   {TriggerSpec::Kind::Either, "either"},
    {TriggerSpec::Kind::Above, "above"}, {TriggerSpec::Kind::Below, "below"},
    {TriggerSpec::Kind::Alarm, "alarm"}, {TriggerSpec::Kind::MotionStart, "motion"},
};
} // namespace

QString TriggerSpec::kindId(Kind kind)
{
    for (const KindName &k : Kinds)
        if (k.kind == kind)
            return QString::fromLatin1(k.id);
    return {};
}

bool TriggerSpec::fires(double previous, double current) const
{
    if (!std::isfinite(current))
        return false;
    switch (kind) {
    case Kind::Above: return current > level;
    case Kind::Below: return current < level;
    case Kind::Rise: return std::isfinite(previous) && previous < level && current >= level;
    case Kind::Fall: return std::isfinite(previous) && previous > level && current <= level;
    case Kind::Either:
        return std::isfinite(previous)
            && ((previous < level && current >= level) || (previous > level && current <= level));
    case Kind::Now:
    case Kind::Alarm:
    case Kind::MotionStart: return false;
    }
    return false;
}

Error TriggerSpec::parse(const QString &text, TriggerSpec *out)
{
    const QStringList parts = text.trimmed().split(QLatin1Char(':'));
    const QString head = parts.value(0).toLower();
    const KindName *found = nullptr;
    for (const KindName &k : Kinds)
        if (head == QLatin1String(k.id))
            found = &k;
    const QString syntax = QStringLiteral("rise:CHANNEL:VALUE, fall:CHANNEL:VALUE, either:CHANNEL:VALUE, "
                                          "above:CHANNEL:VALUE, below:CHANNEL:VALUE, alarm, now");
    if (!found)
        return {ErrorCode::InvalidArgument, tr("Unknown trigger \"%1\": use %2.").arg(text, syntax)};
    TriggerSpec t;
    t.kind = found->kind;
    if (!t.isLevel()) {
        if (parts.size() != 1)
            return {ErrorCode::InvalidArgument, tr("The trigger \"%1\" takes no channel or level.").arg(head)};
        *out = t;
        return Error::none();
    }
    if (parts.size() != 3 || parts.at(1).trimmed().isEmpty())
        return {ErrorCode::InvalidArgument,
                tr("The trigger \"%1\" needs a channel and a level, e.g. %2:speed:500.").arg(text, head)};
    bool ok = false;
    t.channel = parts.at(1).trimmed();
    t.level = parts.at(2).trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(t.level))
        return {ErrorCode::InvalidArgument, tr("The trigger level \"%1\" is not a number.").arg(parts.at(2))};
    *out = t;
    return Error::none();
}

QString TriggerSpec::toString() const
{
    if (!isLevel())
        return kindId(kind);
    return QStringLiteral("%1:%2:%3").arg(kindId(kind), channel, QString::number(level, 'g', 12));
}

} // namespace dd
