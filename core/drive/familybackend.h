#pragma once

#include "core/common/error.h"
#include "core/drive/discovery.h"
#include "core/link/connectionsettings.h"

#include <QObject>

namespace dd {

class Drive;
class TrafficTap;

// One family's way onto a link: opens the transport it needs (serial, CAN, Modbus), makes
// Drive objects for addresses on it and discovery scans. Owned by a DriveConnection; the
// drives and discoveries it creates are its children.
class FamilyBackend : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;

    virtual Family family() const = 0;
    virtual bool open(const ConnectionSettings &settings, TrafficTap *tap, Error *error) = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    // The drive at `address` (created on first use, then the same object).
    virtual Drive *drive(int address) = 0;
    virtual Discovery *createDiscovery(const ScanOptions &options) = 0;
    // Stop every drive on the link at once (the STOP button): emergency where the family
    // has it. Returns when the frames are queued; failures are reported via the replies.
    virtual void stopAll() = 0;
    virtual QString linkDescription() const = 0;

signals:
    void linkLost(const dd::Error &why);
};

} // namespace dd
