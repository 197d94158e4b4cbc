#pragma once

#include "core/common/family.h"
#include "core/drive/drivetypes.h"

#include <QCoreApplication>
#include <QString>

namespace dd {

// Translated wording shared by the bus tree, the overview and the status bar, so that a
// state reads the same everywhere.
class DisplayText
{
    Q_DECLARE_TR_FUNCTIONS(dd::DisplayText)
public:
    static QString familyName(Family family);             // "Servo (CAN)", ...
    static QString driveName(Family family, int address); // "Servo (Modbus) #3"
    static QString motionState(const DriveStatus &s);     // "Running" / "Idle" / "Offline"
    static QString enabledState(const DriveStatus &s);    // "Enabled" / "Disabled"
    static QString alarm(int code);                       // "Alarm 12" / "No alarm"
    static QString position(const DriveStatus &s);        // "12345" / "—"
    static QString capabilityName(Capability c);          // "Jog", "EEPROM operations"
    // A channel's unit ("pulse/s", untranslated from the drive layer: channelUnits()) in the
    // UI language.
    static QString unit(const QString &unit);
    // "Speed [r/min]", the unit translated; just the name without a unit.
    static QString channelLabel(const QString &name, const QString &unit);
    // `text` as a sentence: a full stop added when it ends without one (。 after Chinese).
    static QString sentence(const QString &text);
    // One line in words: "Enabled · moving", "Alarm 12 · Disabled · at rest", "Offline".
    static QString summary(const DriveStatus &s);
};

} // namespace dd
