#pragma once

#include "core/drive/familybackend.h"
#include "core/drive/shuoke/shuokeoptions.h"

#include <QMap>
#include <QPointer>

namespace dd {

class ShuokeDrive;
class ShuokeTransport;

// The `shuoke` family on one link, in any of its four framings (ConnectionSettings::framing,
// options: see ShuokeOptions):
//   rtu / ascii  ShuokeSerialTransport on a SerialLink (default 9600 baud, 50 ms gap);
//   can          ShuokeCanTransport on a CanLink (default 100 kbit/s, bitrate code 12);
//   plc          ShuokePlcTransport on a ModbusLink (registers = "shuoke.plcBase" + command).
// Drive addresses: 1..247 on serial, 1..250 on CAN.
// stopAll(): one broadcast emergency stop (0x3C is broadcast-capable) where the framing has
// broadcasts (not PLC), then an emergency stop to every drive made here, which also ends
// their jog leases.
class ShuokeBackend : public FamilyBackend
{
    Q_OBJECT
public:
    explicit ShuokeBackend(QObject *parent = nullptr);
    ~ShuokeBackend() override;

    Family family() const override { return Family::Shuoke; }
    bool open(const ConnectionSettings &settings, TrafficTap *tap, Error *error) override;
    void close() override;
    bool isOpen() const override;
    Drive *drive(int address) override;
    ShuokeDrive *shuokeDrive(int address);
    Discovery *createDiscovery(const ScanOptions &options) override;
    void stopAll() override;
    QString linkDescription() const override;

    ShuokeTransport *transport() const { return m_transport; }
    const ShuokeOptions &options() const { return m_options; }

private:
    void dropTransport();

    ShuokeOptions m_options;
    ShuokeTransport *m_transport = nullptr;
    QMap<int, QPointer<ShuokeDrive>> m_drives;
    bool m_open = false;
};

} // namespace dd
