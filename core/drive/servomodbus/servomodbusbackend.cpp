#include "core/drive/servomodbus/servomodbusbackend.h"
#include "core/protocol/familytraits.h"

#include "core/drive/servomodbus/servomodbusscanner.h"
#include "core/link/modbuslink.h"

#include <QLoggingCategory>

Q_LOGGING_CATEGORY(lcServoModbus, "drivedesk.drive.servo-modbus")

namespace dd {

ServoModbusBackend::ServoModbusBackend(QObject *parent)
    : FamilyBackend(parent)
{
}

ServoModbusBackend::~ServoModbusBackend()
{
    close();
}

bool ServoModbusBackend::open(const ConnectionSettings &settings, TrafficTap *tap, Error *error)
{
    close();
    if (settings.isCan() || settings.port.isEmpty()) {
        if (error)
            *error = {ErrorCode::InvalidArgument,
                      tr("servo-modbus drives are reached over a serial port (RS485): give a port.")};
        return false;
    }
    Error optionError;
    const ServoModbusOptions options = ServoModbusOptions::fromMap(settings.options, &optionError);
    if (optionError) {
        if (error)
            *error = optionError;
        return false;
    }
    SerialSettings s;
    s.portName = settings.port;
    s.baud = settings.baud > 0 ? settings.baud : familyTraits(Family::ServoModbus).defaultBaud;
    s.responseTimeoutMs = settings.timeoutMs >= 0 ? settings.timeoutMs : DefaultResponseTimeoutMs;
    s.retries = settings.retries >= 0 ? settings.retries : DefaultRetries;
    auto *link = new ModbusLink(this);
    link->setTap(tap);
    // The seed's error reply (code 0x04) also answers a request that arrived damaged.
    link->setRetriedExceptionCode(modbusrtu::ServerDeviceFailure);
    if (!link->open(s, error)) {
        delete link;
        return false;
    }
    m_link = link;
    m_options = options;
    connect(m_link, &ModbusLink::closed, this, &ServoModbusBackend::onLinkClosed);
    qCDebug(lcServoModbus) << "open" << linkDescription();
    return true;
}

void ServoModbusBackend::close()
{
    if (!m_link)
        return;
    ModbusLink *link = m_link;
    m_link = nullptr;
    link->disconnect(this);
    for (auto &d : m_drives)
        delete d.data();
    m_drives.clear();
    link->close();
    link->deleteLater();
}

bool ServoModbusBackend::isOpen() const
{
    return m_link && m_link->isOpen();
}

Drive *ServoModbusBackend::drive(int address)
{
    if (!m_link)
        return nullptr;
    QPointer<ServoModbusDrive> &d = m_drives[address];
    if (!d)
        d = new ServoModbusDrive(m_link, address, m_options, this);
    return d;
}

Discovery *ServoModbusBackend::createDiscovery(const ScanOptions &options)
{
    if (!m_link)
        return nullptr;
    return new ServoModbusScanner(m_link, options, this);
}

void ServoModbusBackend::stopAll()
{
    // The servo-modbus protocol has no stop command (see ServoModbusDrive).
    qCDebug(lcServoModbus) << "stopAll: the servo-modbus protocol has no stop command";
}

QString ServoModbusBackend::linkDescription() const
{
    if (!m_link)
        return QString();
    return tr("%1 @ %2 baud, Modbus RTU (servo-modbus)").arg(m_link->name()).arg(m_link->settings().baud);
}

void ServoModbusBackend::onLinkClosed(const Error &reason)
{
    if (!reason.isError())
        return;
    for (auto &d : m_drives)
        if (d)
            emit d->connectionLost(reason);
    emit linkLost(reason);
}

} // namespace dd
