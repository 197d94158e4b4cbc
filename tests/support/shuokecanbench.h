#pragma once

#include "sim/shuoke/simshuokecandevice.h"
#include "tests/support/shuokehostbench.h"

#include <memory>

namespace dd {

class SimCanBus;
class VirtualCanHub;

// Integration bench for Shuoke over CAN: a SimCanBus of simulated Shuoke drives and a
// DriveConnection (the real ShuokeBackend on a CanLink) on Qt's virtualcan, through a
// VirtualCanHub on a free TCP port (no other test process shares the bus). Every frame the host's TrafficTap
// records is kept in records().
class ShuokeCanBench : public ShuokeHostBench
{
    Q_OBJECT
public:
    explicit ShuokeCanBench(QObject *parent = nullptr);
    ~ShuokeCanBench() override;

    // A started bench with `drives` on its bus and the host connected with `settings`;
    // nullptr, with a warning saying why, when a step fails.
    static std::unique_ptr<ShuokeCanBench> create(const QList<SimShuokeDrive::Config> &drives,
                                                  const ConnectionSettings &settings);

    // False (and `error`) when virtualcan is missing or the bus does not come up.
    bool start(QString *error = nullptr);
    SimShuokeCanDevice *addDrive(const SimShuokeDrive::Config &config);
    // Opens the host side and waits until it is connected; `settings.can` is filled in.
    bool connectHost(ConnectionSettings settings, QString *error = nullptr);

    SimCanBus *bus() const { return m_bus.get(); }
    QList<SimShuokeCanDevice *> devices() const { return m_devices; } // as added
    QString interfaceName() const { return m_interface; }

private:
    std::unique_ptr<VirtualCanHub> m_hub;
    std::unique_ptr<SimCanBus> m_bus;
    QList<SimShuokeCanDevice *> m_devices;
    QString m_interface;
};

} // namespace dd
