#pragma once

#include "core/link/connectionsettings.h"
#include "core/link/trafficrecord.h"
#include "sim/shuoke/simshuokecandevice.h"

#include <QObject>
#include <memory>

namespace dd {

class DriveConnection;
class ShuokeBackend;
class ShuokeDrive;
class SimCanBus;
class VirtualCanHub;

// Integration bench for Shuoke over CAN: a SimCanBus of simulated Shuoke drives and a
// DriveConnection (the real ShuokeBackend on a CanLink) on Qt's virtualcan, through a
// VirtualCanHub on a free TCP port (no other test process shares the bus). Every frame the host's TrafficTap
// records is kept in records().
class ShuokeCanBench : public QObject
{
    Q_OBJECT
public:
    explicit ShuokeCanBench(QObject *parent = nullptr);
    ~ShuokeCanBench() override;

    // False (and `error`) when virtualcan is missing or the bus does not come up.
    bool start(QString *error = nullptr);
    SimShuokeCanDevice *addDrive(const SimShuokeDrive::Config &config);
    // Opens the host side and waits until it is connected; `settings.can` is filled in.
    bool connectHost(ConnectionSettings settings, QString *error = nullptr);

    SimCanBus *bus() const { return m_bus.get(); }
    DriveConnection *connection() const { return m_connection.get(); }
    ShuokeBackend *backend() const;
    ShuokeDrive *drive(int address) const;
    QString interfaceName() const { return m_interface; }

    const QList<TrafficRecord> &records() const { return m_records; }
    int txCount() const;

private:
    std::unique_ptr<VirtualCanHub> m_hub;
    std::unique_ptr<SimCanBus> m_bus;
    std::unique_ptr<DriveConnection> m_connection;
    QString m_interface;
    QList<TrafficRecord> m_records;
};

} // namespace dd
