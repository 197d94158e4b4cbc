#pragma once

#include "common/error.h"
#include "drive/connectionsettings.h"

#include <QObject>
#include <QStringList>

class QThread;

namespace dd {

class SimBenchWorker;

// The demo bench: one simulated drive of each family, each on its own link, running on a
// thread of its own (not the caller's), so that a busy or blocked GUI thread never stalls
// the simulator:
//   - servo-modbus: a SimServoModbusDrive on a pty (SimSerialBus);
//   - shuoke: a SimShuokeDrive (RTU framing) on a second pty;
//   - servo-can: a SimServoCanDrive on a virtual CAN bus (virtualcan, on a private TCP port
//     "tcp://127.0.0.1:<free port>/can0", so it never meets another bench or test).
// connections() returns what to connect to. Each drive answers at FirstAddress.
class SimBench : public QObject
{
    Q_OBJECT
public:
    static constexpr int FirstAddress = 1;
    static constexpr int LastScannedAddress = 4;   // the demo scans 1..4

    explicit SimBench(QObject *parent = nullptr);
    ~SimBench() override;   // stops the bench (the links' clients see the adapters vanish)

    // Creates the simulators on the bench thread; returns when they are ready.
    Error start();
    void stop();
    bool isRunning() const { return m_running; }

    QList<ConnectionSettings> connections() const { return m_connections; }
    // One line per simulated drive, for logs and the About box.
    QStringList describe() const { return m_descriptions; }
    QThread *thread() const { return m_thread; }

private:
    QThread *m_thread = nullptr;
    SimBenchWorker *m_worker = nullptr;   // lives on m_thread
    QList<ConnectionSettings> m_connections;
    QStringList m_descriptions;
    bool m_running = false;
};

} // namespace dd
