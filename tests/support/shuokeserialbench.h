#pragma once

#include "core/link/connectionsettings.h"
#include "core/link/trafficrecord.h"
#include "sim/shuoke/simshuokeserialdevice.h"

#include <QObject>
#include <memory>

namespace dd {

class DriveConnection;
class DriveReply;
class ShuokeBackend;
class ShuokeDrive;
class SimSerialBus;

// Integration bench for the Shuoke serial framings: a pty with a SimSerialBus of simulated
// Shuoke drives on one end and a DriveConnection (the real ShuokeBackend on QSerialPort)
// on the other. Every frame the host's TrafficTap records is kept in records().
class ShuokeSerialBench : public QObject
{
    Q_OBJECT
public:
    explicit ShuokeSerialBench(QObject *parent = nullptr);
    ~ShuokeSerialBench() override;

    // Creates the pty and the bus; false (and `error`) when ptys are unavailable.
    bool start(QString *error = nullptr);
    SimShuokeSerialDevice *addDrive(const SimShuokeDrive::Config &config,
                                    SimShuokeSerialDevice::Framing framing = SimShuokeSerialDevice::Framing::Rtu,
                                    shuoke::AsciiCheck check = shuoke::AsciiCheck::PlainSum);
    // Opens the host side; `settings.port` is filled in, family set to shuoke.
    bool connectHost(ConnectionSettings settings, QString *error = nullptr);

    SimSerialBus *bus() const { return m_bus.get(); }
    DriveConnection *connection() const { return m_connection.get(); }
    ShuokeBackend *backend() const;
    ShuokeDrive *drive(int address) const;
    QString portPath() const;

    const QList<TrafficRecord> &records() const { return m_records; }
    void clearRecords() { m_records.clear(); }
    int txCount() const;

    // Waits for the reply to finish (event loop running); false on timeout.
    static bool wait(DriveReply *reply, int timeoutMs = 5000);

private:
    std::unique_ptr<SimSerialBus> m_bus;
    std::unique_ptr<DriveConnection> m_connection;
    QString m_port;
    QList<TrafficRecord> m_records;
};

} // namespace dd
