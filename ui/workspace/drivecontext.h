#pragma once

#include "core/common/family.h"
#include "core/drive/drivetypes.h"

namespace dd {

class AlarmLog;
class DriveHub;
class DriveParameters;

// Which drive a panel works on and what it may do there. Panels reach the drive only
// through `hub` (DriveHub::run with `connectionId` and `address`), never directly.
struct DriveContext
{
    DriveHub *hub = nullptr;
    int connectionId = 0;
    int address = 0;
    Family family = Family::ServoModbus;
    Capabilities capabilities;
    // The drive's parameter values, shared by all its panels (made by the workspace; a
    // panel made without one gets its own).
    DriveParameters *parameters = nullptr;
    // The drive's alarm history since it was found (kept by the workspace; a panel made
    // without one gets its own).
    AlarmLog *alarms = nullptr;

    bool isValid() const { return hub && connectionId > 0; }
    bool can(Capability c) const { return capabilities.testFlag(c); }
    bool sameDrive(const DriveContext &o) const { return connectionId == o.connectionId && address == o.address; }
};

} // namespace dd
