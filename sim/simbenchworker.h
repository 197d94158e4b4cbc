#pragma once

#include "common/error.h"
#include "drive/connectionsettings.h"

#include <QObject>
#include <QStringList>

namespace dd {

class SimCanBus;
class SimSerialBus;
class VirtualCanHub;

// SimBench's objects on the bench thread: the buses and the simulated drives. Created,
// built and deleted on that thread only.
class SimBenchWorker : public QObject
{
    Q_OBJECT
public:
    explicit SimBenchWorker(QObject *parent = nullptr);
    ~SimBenchWorker() override;

    // Creates every bus and drive; the serial ones are ready at once, the CAN bus emits
    // ready() once its plugin has connected (or failed() after SimCanBus::ConnectTimeoutMs).
    Error build(int address);
    QList<ConnectionSettings> connections() const { return m_connections; }
    QStringList describe() const { return m_descriptions; }

signals:
    void ready();
    void failed(const dd::Error &error);

private:
    Error addCanBus(int station);

    QList<SimSerialBus *> m_serialBuses;
    VirtualCanHub *m_canHub = nullptr;
    SimCanBus *m_canBus = nullptr;
    QList<ConnectionSettings> m_connections;
    QStringList m_descriptions;
};

} // namespace dd
