#include "core/link/modbuslink.h"

#include "core/link/modbuslinkprivate.h"

#include <QModbusRtuSerialClient>
#include <QVariant>

namespace dd {

ModbusLink::ModbusLink(QObject *parent)
    : QObject(parent)
    , d(new Private(this))
{
}

ModbusLink::~ModbusLink()
{
    d->close({ErrorCode::Cancelled, tr("The Modbus link was destroyed.")});
    delete d;
}

void ModbusLink::setTap(TrafficTap *tap)
{
    d->m_tap = tap;
}
TrafficTap *ModbusLink::tap() const
{
    return d->m_tap;
}

bool ModbusLink::open(const SerialSettings &settings, Error *error)
{
    if (!d->open(settings, error))
        return false;
    emit opened();
    return true;
}

void ModbusLink::close()
{
    if (!d->isOpen() && !d->m_client)
        return;
    d->close({ErrorCode::Cancelled, tr("The serial port %1 was closed.").arg(d->m_settings.portName)});
    emit closed(Error::none());
}

bool ModbusLink::isOpen() const
{
    return d->isOpen();
}
const SerialSettings &ModbusLink::settings() const
{
    return d->m_settings;
}
QString ModbusLink::name() const
{
    return d->m_settings.portName;
}

bool ModbusLink::setBaudRate(qint32 baud)
{
    if (!d->isOpen() || !isIdle() || baud <= 0)
        return false;
    if (baud == d->m_settings.baud)
        return true;
    const qint32 old = d->m_settings.baud;
    d->m_settings.baud = baud;
    d->m_client->setConnectionParameter(QModbusDevice::SerialBaudRateParameter, baud);
    Error e;
    if (!d->reconnect(&e)) {
        d->m_settings.baud = old;
        d->close(e);
        emit closed(e);
        return false;
    }
    // Whatever was on the line belonged to the other baud rate.
    d->m_taintedUntilUs.clear();
    d->m_owed.clear();
    return true;
}

void ModbusLink::setResponseTimeoutMs(int ms)
{
    d->m_settings.responseTimeoutMs = std::max(0, ms);
}
void ModbusLink::setRetries(int retries)
{
    d->m_settings.retries = std::max(0, retries);
}
void ModbusLink::setRetriedExceptionCode(int code)
{
    d->m_retriedExceptionCode = code;
}
void ModbusLink::setMinGapMs(int ms)
{
    d->m_settings.minGapMs = std::max(0, ms);
}
void ModbusLink::setMinCommandSpacingMs(int ms)
{
    d->m_settings.minCommandSpacingMs = std::max(0, ms);
}

LinkReply *ModbusLink::readHoldingRegisters(int serverAddress, int start, int count, int timeoutMs)
{
    ModbusRequest r;
    r.pdu.address = static_cast<quint8>(serverAddress);
    r.pdu.function = modbusrtu::ReadHoldingRegisters;
    r.pdu.start = static_cast<quint16>(start);
    r.pdu.count = static_cast<quint16>(count);
    r.timeoutMs = timeoutMs;
    return send(r);
}

LinkReply *ModbusLink::writeRegisters(int serverAddress, int start, const QList<quint16> &values, int timeoutMs)
{
    ModbusRequest r;
    r.pdu.address = static_cast<quint8>(serverAddress);
    r.pdu.function = modbusrtu::WriteMultipleRegisters;
    r.pdu.start = static_cast<quint16>(start);
    r.pdu.count = static_cast<quint16>(values.size());
    r.pdu.values = values;
    r.timeoutMs = timeoutMs;
    return send(r);
}

LinkReply *ModbusLink::writeSingleRegister(int serverAddress, int reg, quint16 value, int timeoutMs)
{
    ModbusRequest r;
    r.pdu.address = static_cast<quint8>(serverAddress);
    r.pdu.function = modbusrtu::WriteSingleRegister;
    r.pdu.start = static_cast<quint16>(reg);
    r.pdu.count = 1;
    r.pdu.values = {value};
    r.timeoutMs = timeoutMs;
    return send(r);
}

LinkReply *ModbusLink::send(const ModbusRequest &request)
{
    return d->enqueue(request);
}

void ModbusLink::cancelAll(const Error &why)
{
    d->failAll(why);
}

bool ModbusLink::isIdle() const
{
    return !d->m_current && d->m_queue.isEmpty();
}
int ModbusLink::queuedCount() const
{
    return int(d->m_queue.size()) + (d->m_current ? 1 : 0);
}
quint64 ModbusLink::timeoutCount() const
{
    return d->m_timeouts;
}
quint64 ModbusLink::retryCount() const
{
    return d->m_retries;
}
quint64 ModbusLink::checksumErrorCount() const
{
    return d->m_checksumErrors;
}
quint64 ModbusLink::lateReplyCount() const
{
    return d->m_lateReplies;
}
quint64 ModbusLink::reconnectCount() const
{
    return d->m_reconnects;
}
bool ModbusLink::seesRawBytes() const
{
    return d->m_sniffer.isActive();
}
qint64 ModbusLink::wireTimeUs(qsizetype bytes) const
{
    return d->wireTimeUs(bytes);
}

int ModbusLink::defaultTimeoutMs(const modbusrtu::Request &pdu) const
{
    ModbusRequest r;
    r.pdu = pdu;
    return d->effectiveTimeoutMs(r);
}

int ModbusLink::interFrameDelayUs() const
{
    return d->m_client ? d->m_client->interFrameDelay() : 0;
}

} // namespace dd
