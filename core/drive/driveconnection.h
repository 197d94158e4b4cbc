#pragma once

#include "core/common/error.h"
#include "core/drive/discovery.h"
#include "core/link/connectionsettings.h"

#include <QObject>

namespace dd {

class Drive;
class FamilyBackend;
class TrafficTap;

// The application's handle on one link: the family backend that speaks on it, the
// traffic tap, and the drives found there. The CLI makes one; the GUI makes one per
// connection, on its I/O thread.
class DriveConnection : public QObject
{
    Q_OBJECT
public:
    explicit DriveConnection(QObject *parent = nullptr);
    ~DriveConnection() override;

    bool open(const ConnectionSettings &settings, Error *error = nullptr);
    void close();
    bool isOpen() const;

    const ConnectionSettings &settings() const { return m_settings; }
    TrafficTap *tap() const { return m_tap; }
    FamilyBackend *backend() const { return m_backend; }

    Drive *drive(int address); // nullptr when closed
    Discovery *createDiscovery(const ScanOptions &options);
    void stopAll();

signals:
    void linkLost(const dd::Error &why);

private:
    ConnectionSettings m_settings;
    TrafficTap *m_tap = nullptr;
    FamilyBackend *m_backend = nullptr;
};

} // namespace dd
