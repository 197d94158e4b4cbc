#pragma once

#include "core/common/error.h"
#include "core/common/family.h"
#include "core/link/connectionsettings.h"

#include <QObject>
#include <QStringList>

class QThread;

namespace dd {

class DemoBenchWorker;

// The demo bench (drivedesk --demo, File → Demo bench): one simulated drive of each family,
// each on a bus of its own (a SimBench each), all running on a thread of their own — not
// the caller's — so that a busy or blocked GUI thread never stalls the simulator:
//   - servo-modbus: a SimServoModbusDrive on a pty, 19200 baud, with the simulator's demo
//     motion (the servo-modbus protocol cannot move an axis: on a real machine the drive
//     follows its control inputs, so the demo axis moves by itself to give the monitor
//     and the trend something to show);
//   - shuoke: a SimShuokeDrive (RTU framing) on a second pty (when the build has it);
//   - servo-can: a SimServoCanDrive on virtualcan through a private low-delay hub on a free
//     local port ("tcp://127.0.0.1:<port>/can0"), so it never meets another bench or test.
// Every drive answers at `Address`. start() creates everything; the serial drives answer
// at once, the CAN bus is up when ready() is emitted: connect to connections() then.
class DemoBench : public QObject
{
    Q_OBJECT
public:
    static constexpr int Address = 1;
    static constexpr int ScanFrom = 1; // the demo scans 1..4
    static constexpr int ScanTo = 4;

    explicit DemoBench(QObject *parent = nullptr);
    ~DemoBench() override; // stops the bench (the links' clients see the adapters vanish)

    // The closed-loop drives carry a compliant load resonating at this frequency (0: rigid).
    // Default: the environment variable DRIVEDESK_DEMO_RESONANCE_HZ (docs/tuning.md).
    void setResonanceHz(double hz) { m_resonanceHz = hz; }
    double resonanceHz() const { return m_resonanceHz; }

    // Creates the simulators on the bench thread; fails at once if one cannot be created.
    Error start();
    void stop();
    bool isRunning() const { return m_running; }
    bool isReady() const { return m_ready; }

    // What to connect to (valid after start()), one link per family.
    QList<ConnectionSettings> connections() const { return m_connections; }
    // One line per bus ("servo-modbus: pty: /dev/pts/5"), for logs.
    QStringList describe() const { return m_descriptions; }
    QThread *benchThread() const { return m_thread; }
    // The families whose demo drive can raise an alarm (Demo → Inject alarm), and raising one
    // (code 0: the alarm goes, as after the cause is removed); false when that drive cannot.
    QList<Family> alarmFamilies() const { return m_alarmFamilies; }
    bool injectAlarm(Family family, int code);

signals:
    void ready();
    void failed(const dd::Error &error);

private:
    QThread *m_thread = nullptr;
    DemoBenchWorker *m_worker = nullptr; // lives on m_thread
    QList<ConnectionSettings> m_connections;
    QStringList m_descriptions;
    QList<Family> m_alarmFamilies;
    bool m_running = false;
    bool m_ready = false;
    double m_resonanceHz = 0.0;
};

} // namespace dd
