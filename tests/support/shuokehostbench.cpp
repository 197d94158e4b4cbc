#include "tests/support/shuokehostbench.h"

#include "core/drive/driveconnection.h"
#include "core/drive/shuoke/shuokebackend.h"
#include "core/drive/shuoke/shuokedrive.h"
#include "core/link/traffictap.h"

namespace dd {

ShuokeHostBench::ShuokeHostBench(QObject *parent)
    : QObject(parent)
{
}

ShuokeHostBench::~ShuokeHostBench() = default;

bool ShuokeHostBench::openHost(ConnectionSettings settings, QString *error)
{
    settings.family = Family::Shuoke;
    m_connection = std::make_unique<DriveConnection>();
    connect(m_connection->tap(), &TrafficTap::frameRecorded, this,
            [this](const TrafficRecord &r) { m_records.append(r); });
    Error e;
    if (!m_connection->open(settings, &e)) {
        if (error)
            *error = e.message;
        return false;
    }
    return true;
}

void ShuokeHostBench::closeHost()
{
    m_connection.reset();
}

ShuokeBackend *ShuokeHostBench::backend() const
{
    return m_connection ? qobject_cast<ShuokeBackend *>(m_connection->backend()) : nullptr;
}

ShuokeDrive *ShuokeHostBench::drive(int address) const
{
    return backend() ? backend()->shuokeDrive(address) : nullptr;
}

int ShuokeHostBench::txCount() const
{
    int n = 0;
    for (const TrafficRecord &r : m_records)
        if (r.direction == TrafficRecord::Direction::Tx)
            ++n;
    return n;
}

} // namespace dd
