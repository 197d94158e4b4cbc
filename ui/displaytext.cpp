#include "displaytext.h"

#include <QLocale>

namespace dd {

QString DisplayText::familyName(Family family)
{
    switch (family) {
    case Family::ServoCan: return tr("Servo (CAN)");
    case Family::ServoModbus: return tr("Servo (Modbus)");
    case Family::Shuoke: return tr("Shuoke stepper");
    }
    return familyId(family);
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
    QString text = tr("%1, %2").arg(motionState(s), enabledState(s).toLower());
    if (s.alarmCode)
        text = tr("%1, %2").arg(text, alarm(s.alarmCode).toLower());
    return text;
}

} // namespace dd
