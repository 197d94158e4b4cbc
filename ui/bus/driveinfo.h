#pragma once

#include "core/drive/drivetypes.h"

#include <QList>
#include <QMap>
#include <QMetaType>
#include <functional>

namespace dd {

class DriveHub;
struct Error;

// A snapshot of what the I/O thread knows about one drive, taken on the I/O thread and
// handed to the GUI as a value: identity, capabilities (with the reason for each missing
// one), channels and the last status.
struct DriveInfo
{
    int connectionId = 0;
    int address = 0;
    DriveIdentity identity;
    Capabilities capabilities;
    QMap<Capability, QString> unsupportedReasons; // translated, for missing capabilities
    QList<ChannelInfo> channels;
    DriveStatus status;
    bool valid = false; // false: the drive could not be reached (see the error)

    QString reason(Capability c) const { return unsupportedReasons.value(c); }

    // Every capability bit, in display order.
    static QList<Capability> allCapabilities();
    // Translated display name of a capability ("Jog", "EEPROM operations", ...).
    static QString capabilityName(Capability c);
};

// Refreshes the identity of the drive at (`connectionId`, `address`) through the hub and
// calls `done` (on the hub's thread) with the snapshot; a failed identity read still
// reports capabilities and channels, with `error` set.
void fetchDriveInfo(DriveHub *hub, int connectionId, int address,
                    std::function<void(const DriveInfo &info, const Error &error)> done);

} // namespace dd

Q_DECLARE_METATYPE(dd::DriveInfo)
