#pragma once

#include "core/drive/familybackend.h"
#include "core/drive/servomodbus/servomodbusdrive.h"

#include <QHash>
#include <QPointer>

namespace dd {

// The servo-modbus family on a ModbusLink (Modbus RTU on SerialLink).
//
// Defaults where the seed is silent: 19200 baud (ConnectionSettings::baud = 0; the seed gives
// no rate, 19200 is this drive class's most common factory setting; a scan sweeps the
// others), a response allowance of 100 ms beyond the wire time, 2 retries. Options:
// ServoModbusOptions (servo-modbus.positionRule, servo-modbus.eeFormat, ...).
// The family has no stop command: stopAll() sends nothing.
class ServoModbusBackend : public FamilyBackend
{
    Q_OBJECT
public:
    static constexpr int DefaultResponseTimeoutMs = 100;
    static constexpr int DefaultRetries = 2;

    explicit ServoModbusBackend(QObject *parent = nullptr);
    ~ServoModbusBackend() override;

    Family family() const override { return Family::ServoModbus; }
    bool open(const ConnectionSettings &settings, TrafficTap *tap, Error *error) override;
    void close() override;
    bool isOpen() const override;
    Drive *drive(int address) override;
    Discovery *createDiscovery(const ScanOptions &options) override;
    void stopAll() override;
    QString linkDescription() const override;

    ModbusLink *link() const { return m_link; }
    const ServoModbusOptions &options() const { return m_options; }

private:
    void onLinkClosed(const Error &reason);

    ModbusLink *m_link = nullptr;
    ServoModbusOptions m_options;
    QHash<int, QPointer<ServoModbusDrive>> m_drives;
};

} // namespace dd
