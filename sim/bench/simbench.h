#pragma once

#include "core/common/error.h"
#include "core/link/connectionsettings.h"
#include "sim/bench/simbenchoptions.h"

#include <QJsonObject>
#include <QObject>
#include <memory>

namespace dd {

class SimCanBus;
class SimSerialBus;
class SimSerialDevice;
class VirtualCanHub;

// One simulated bus with drives of one family on it: a pty (SimSerialBus) or a CAN bus
// (SimCanBus; for virtualcan a private low-delay hub when the interface names no server).
// Lives in the thread that created it; the motor models advance on its event loop.
class SimBench : public QObject
{
    Q_OBJECT
public:
    explicit SimBench(QObject *parent = nullptr);
    ~SimBench() override;

    Error start(const SimBenchOptions &options);
    void stop(); // saves the state file if one was given
    Error saveState() const;
    bool isRunning() const;

    const SimBenchOptions &options() const { return m_options; }
    // Where a client connects, as drivedesk-sim prints it: "pty: /dev/pts/5" or
    // "can: virtualcan:tcp://127.0.0.1:40123/can0".
    QString where() const;
    // The settings a DriveDesk client uses to reach these drives.
    ConnectionSettings clientSettings() const;

    // Power loss on every drive of the bench (they hear and answer nothing) or back.
    void setSilent(bool silent);
    // Injects an alarm (0 clears) into the drive at `address`; false when there is none.
    bool injectAlarm(int address, int code);
    // Whether this bench's drives take injectAlarm() (the families with an alarm code).
    bool canInjectAlarm() const;

    SimSerialBus *serialBus() const { return m_serial; }
    SimCanBus *canBus() const { return m_can; }

private:
    Error startSerial();
    Error startCan();
    QJsonObject stateOf() const;
    Error applyState(const QJsonObject &state);

    SimBenchOptions m_options;
    SimSerialBus *m_serial = nullptr;
    SimCanBus *m_can = nullptr;
    VirtualCanHub *m_hub = nullptr;
    QString m_clientCan; // the CAN interface a client should open
    QString m_ptyPath;
};

} // namespace dd
