#include "ui/common/displaytext.h"

#include "core/protocol/familytraits.h"

#include <QLocale>

namespace dd {

QString DisplayText::familyName(Family family)
{
    return familyTraits(family).displayName();
}

QString DisplayText::driveName(Family family, int address)
{
    return tr("%1 #%2").arg(familyName(family)).arg(address);
}

QString DisplayText::motionState(const DriveStatus &s)
{
    if (s.updatedMs == 0 && !s.online)
        return tr("Unknown");
    if (!s.online)
        return tr("Offline");
    return s.running ? tr("Running") : tr("Idle");
}

QString DisplayText::enabledState(const DriveStatus &s)
{
    return s.enabled ? tr("Enabled") : tr("Disabled");
}

QString DisplayText::alarm(int code)
{
    return code ? tr("Alarm %1").arg(code) : tr("No alarm");
}

QString DisplayText::position(const DriveStatus &s)
{
    return s.positionValid ? QLocale().toString(s.position) : QStringLiteral("—");
}

QString DisplayText::summary(const DriveStatus &s)
{
    if (!s.online)
        return motionState(s);
    // In words, power stage first: "Enabled · moving", "Disabled · at rest".
    const QString motion = s.running ? tr("moving") : tr("at rest");
    QString text = tr("%1 · %2").arg(enabledState(s), motion);
    if (s.alarmCode)
        text = tr("%1 · %2").arg(alarm(s.alarmCode), text);
    return text;
}

QString DisplayText::sentence(const QString &text)
{
    const QString t = text.trimmed();
    if (t.isEmpty())
        return t;
    const QChar last = t.back();
    if (QStringLiteral(".!?。！？…").contains(last))
        return t;
    const bool chinese = last.unicode() >= 0x2E80; // CJK and full-width punctuation
    return t + (chinese ? QStringLiteral("。") : QStringLiteral("."));
}

QString DisplayText::capabilityName(Capability c)
{
    switch (c) {
    case Capability::ReadParameters: return tr("Read parameters");
    case Capability::WriteParameters: return tr("Write parameters");
    case Capability::Monitor: return tr("Live monitor");
    case Capability::Jog: return tr("Jog");
    case Capability::MoveRelative: return tr("Relative move");
    case Capability::MoveAbsolute: return tr("Absolute move");
    case Capability::Home: return tr("Homing");
    case Capability::SetPosition: return tr("Set position");
    case Capability::Enable: return tr("Enable / disable");
    case Capability::Stop: return tr("Stop");
    case Capability::EmergencyStop: return tr("Emergency stop");
    case Capability::ReadAlarm: return tr("Read alarm");
    case Capability::ClearAlarm: return tr("Clear alarm");
    case Capability::EeOperations: return tr("EEPROM operations");
    }
    return capabilityId(c);
}

QString DisplayText::unit(const QString &unit)
{
    return channelUnitText(unit);
}

QString DisplayText::channelLabel(const QString &name, const QString &unit)
{
    return unit.isEmpty() ? name : tr("%1 [%2]").arg(name, DisplayText::unit(unit));
}

} // namespace dd
