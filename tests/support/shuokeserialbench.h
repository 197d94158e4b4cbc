#pragma once

#include "sim/shuoke/simshuokeserialdevice.h"
#include "tests/support/shuokehostbench.h"

#include <memory>

namespace dd {

class DriveReply;
class SimSerialBus;

// Integration bench for the Shuoke serial framings: a pty with a SimSerialBus of simulated
// Shuoke drives on one end and a DriveConnection (the real ShuokeBackend on QSerialPort)
// on the other. Every frame the host's TrafficTap records is kept in records().
class ShuokeSerialBench : public ShuokeHostBench
{
    Q_OBJECT
public:
    explicit ShuokeSerialBench(QObject *parent = nullptr);
    ~ShuokeSerialBench() override;

    // A started bench with `drives` on its bus (in `framing`, with `check`) and the host
    // connected with `settings`; nullptr, with a warning saying why, when a step fails.
    static std::unique_ptr<ShuokeSerialBench> create(
        const QList<SimShuokeDrive::Config> &drives, const ConnectionSettings &settings,
        SimShuokeSerialDevice::Framing framing = SimShuokeSerialDevice::Framing::Rtu,
        shuoke::AsciiCheck check = shuoke::AsciiCheck::PlainSum);

    // Creates the pty and the bus; false (and `error`) when ptys are unavailable.
    bool start(QString *error = nullptr);
    SimShuokeSerialDevice *addDrive(const SimShuokeDrive::Config &config,
                                    SimShuokeSerialDevice::Framing framing = SimShuokeSerialDevice::Framing::Rtu,
                                    shuoke::AsciiCheck check = shuoke::AsciiCheck::PlainSum);
    // Opens the host side; `settings.port` is filled in, family set to shuoke.
    bool connectHost(ConnectionSettings settings, QString *error = nullptr);

    SimSerialBus *bus() const { return m_bus.get(); }
    QList<SimShuokeSerialDevice *> devices() const { return m_devices; } // as added
    QString portPath() const;

    // Waits for the reply to finish (event loop running); false on timeout.
    static bool wait(DriveReply *reply, int timeoutMs = 5000);

private:
    std::unique_ptr<SimSerialBus> m_bus;
    QList<SimShuokeSerialDevice *> m_devices;
    QString m_port;
};

} // namespace dd
