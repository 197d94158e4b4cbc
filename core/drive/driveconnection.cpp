#include "core/drive/driveconnection.h"
#include "core/drive/familytable.h"

#include "core/drive/drive.h"
#include "core/drive/familybackend.h"
#include "core/link/traffictap.h"

namespace dd {

DriveConnection::DriveConnection(QObject *parent)
    : QObject(parent)
    , m_tap(new TrafficTap(this))
{
}

DriveConnection::~DriveConnection()
{
    close();
}

bool DriveConnection::open(const ConnectionSettings &settings, Error *error)
{
    close();
    m_settings = settings;
    FamilyBackend *backend = createFamilyBackend(settings.family, this);
    if (!backend) {
        if (error)
            *error = {ErrorCode::NotSupported,
                      tr("The %1 family is not available in this build.").arg(familyId(settings.family))};
        return false;
    }
    Error e;
    if (!backend->open(settings, m_tap, &e)) {
        delete backend;
        if (error)
            *error = e;
        return false;
    }
    m_backend = backend;
    connect(backend, &FamilyBackend::linkLost, this, &DriveConnection::linkLost);
    return true;
}

void DriveConnection::close()
{
    if (!m_backend)
        return;
    m_backend->close();
    delete m_backend;
    m_backend = nullptr;
}

bool DriveConnection::isOpen() const
{
    return m_backend && m_backend->isOpen();
}

Drive *DriveConnection::drive(int address)
{
    return m_backend ? m_backend->drive(address) : nullptr;
}

Discovery *DriveConnection::createDiscovery(const ScanOptions &options)
{
    return m_backend ? m_backend->createDiscovery(options) : nullptr;
}

void DriveConnection::stopAll()
{
    if (m_backend)
        m_backend->stopAll();
}

} // namespace dd
