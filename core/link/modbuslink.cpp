#include "core/link/modbuslink.h"

#include "core/common/hextext.h"
#include "core/link/modbusreplymatcher.h"
#include "core/link/seriallink.h"
#include "core/link/wiretime.h"

#include <cmath>

namespace dd {

namespace {
qsizetype requestBytes(const modbusrtu::Request &pdu)
{
    return pdu.function == modbusrtu::WriteMultipleRegisters ? 9 + 2 * pdu.values.size() : 8;
}
} // namespace

ModbusLink::ModbusLink(QObject *parent)
    : QObject(parent)
    , m_serial(new SerialLink(this))
{
    m_serial->setStrayPeers(&ModbusReplyMatcher::peersIn);
    connect(m_serial, &SerialLink::opened, this, &ModbusLink::opened);
    connect(m_serial, &SerialLink::closed, this, &ModbusLink::closed);
    connect(m_serial, &SerialLink::idle, this, &ModbusLink::idle);
    connect(m_serial, &SerialLink::strayBytes, this, &ModbusLink::strayBytes);
}

ModbusLink::~ModbusLink()
{
    m_serial->cancelAll({ErrorCode::Cancelled, tr("The Modbus link was destroyed.")});
}

void ModbusLink::setTap(TrafficTap *tap)
{
    m_serial->setTap(tap);
}
TrafficTap *ModbusLink::tap() const
{
    return m_serial->tap();
}

bool ModbusLink::open(const SerialSettings &settings, Error *error)
{
    if (!m_serial->open(settings, error))
        return false;
    m_serial->setInterFrameGapUs(interFrameGapUs(settings.baud, settings.bitsPerChar));
    m_serial->setSamePeerGapUs(sameDriveGapUs(settings.baud, settings.bitsPerChar));
    return true;
}

void ModbusLink::close()
{
    m_serial->close();
}

bool ModbusLink::isOpen() const
{
    return m_serial->isOpen();
}
const SerialSettings &ModbusLink::settings() const
{
    return m_serial->settings();
}
QString ModbusLink::name() const
{
    return m_serial->name();
}

bool ModbusLink::setBaudRate(qint32 baud)
{
    if (!isOpen() || !isIdle() || baud <= 0)
        return false;
    if (baud == settings().baud)
        return true;
    if (!m_serial->setBaudRate(baud))
        return false;
    m_serial->setInterFrameGapUs(interFrameGapUs(baud, settings().bitsPerChar));
    m_serial->setSamePeerGapUs(sameDriveGapUs(baud, settings().bitsPerChar));
    return true;
}

void ModbusLink::setResponseTimeoutMs(int ms)
{
    m_serial->setResponseTimeoutMs(std::max(0, ms));
}
void ModbusLink::setRetries(int retries)
{
    m_serial->setRetries(std::max(0, retries));
}
void ModbusLink::setRetriedExceptionCode(int code)
{
    m_retriedExceptionCode = code;
}
void ModbusLink::setMinGapMs(int ms)
{
    m_serial->setMinGapMs(std::max(0, ms));
}
void ModbusLink::setMinCommandSpacingMs(int ms)
{
    m_serial->setMinCommandSpacingMs(std::max(0, ms));
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
    auto *outer = new LinkReply(this);
    if (!isOpen()) {
        outer->finishWithError({ErrorCode::LinkClosed, tr("The serial port is not open.")});
        return outer;
    }
    modbusrtu::Request pdu = request.pdu;
    const quint8 fc = pdu.function;
    if (fc == modbusrtu::WriteMultipleRegisters)
        pdu.count = static_cast<quint16>(pdu.values.size());
    else if (fc == modbusrtu::WriteSingleRegister)
        pdu.count = 1;
    const bool valid = (fc == modbusrtu::ReadHoldingRegisters && pdu.address != 0)
        || (fc == modbusrtu::WriteSingleRegister && pdu.values.size() == 1) || fc == modbusrtu::WriteMultipleRegisters;
    const QByteArray adu = valid && pdu.address <= 247 ? modbusrtu::encodeRequest(pdu) : QByteArray();
    if (adu.isEmpty()) {
        outer->finishWithError({ErrorCode::InvalidArgument,
                                tr("Invalid Modbus request (function %1, address %2, %3 registers): nothing "
                                   "was sent.")
                                    .arg(hexText(fc, 2))
                                    .arg(pdu.address)
                                    .arg(fc == modbusrtu::ReadHoldingRegisters ? pdu.count : pdu.values.size())});
        return outer;
    }
    SerialRequest s;
    s.bytes = adu;
    s.retries = request.retries;
    s.note = request.note;
    s.urgent = request.urgent;
    s.peer = pdu.address;
    if (pdu.address == modbusrtu::BroadcastAddress) {
        s.quietAfterUs = qint64(BroadcastTurnaroundMs) * 1000; // no reply; servers act meanwhile
    } else {
        const ModbusReplyMatcher matcher(pdu, name());
        s.matcher = matcher.matcher();
        s.expectedReplyBytes = std::max(modbusrtu::ExceptionReplySize, modbusrtu::expectedReplySize(pdu));
        s.timeoutMs = request.timeoutMs >= 0 ? request.timeoutMs : defaultTimeoutMs(pdu);
        s.quietAfterTimeoutUs = request.quietAfterTimeoutUs;
        s.firstByteTimeoutUs = request.firstByteTimeoutUs;
        s.describeTimeout = [matcher](int ms, const QByteArray &unmatched) {
            return matcher.describeTimeout(ms, unmatched);
        };
        s.describeCorrupt = matcher.describeCorrupt();
    }
    transmit(outer, s, pdu, 0);
    return outer;
}

void ModbusLink::transmit(LinkReply *outer, const SerialRequest &s, const modbusrtu::Request &pdu, int attemptsBefore)
{
    LinkReply *inner = m_serial->send(s);
    inner->setParent(outer); // a caller who deletes its reply withdraws the request
    connect(inner, &LinkReply::finished, outer,
            [this, outer, inner, s, pdu, attemptsBefore] { finishFrom(outer, inner, s, pdu, attemptsBefore); });
}

void ModbusLink::finishFrom(LinkReply *outer, LinkReply *inner, const SerialRequest &s, const modbusrtu::Request &pdu,
                            int attemptsBefore)
{
    const int attempts = attemptsBefore + inner->attempts();
    outer->setAttempts(attempts);
    outer->setRoundTripUs(inner->roundTripUs());
    if (inner->error().isError()) {
        outer->finishWithError(inner->error());
        return;
    }
    if (pdu.address == modbusrtu::BroadcastAddress) {
        outer->finishWithRegisters({});
        return;
    }
    const QByteArray frame = inner->frame();
    const auto decoded = modbusrtu::decodeReply(frame, pdu); // the matcher took only what decodes
    if (!decoded.ok()) {
        outer->finishWithError({ErrorCode::Malformed,
                                tr("The reply from address %1 on %2 does not fit the request (%3).")
                                    .arg(pdu.address)
                                    .arg(name(), decoded.error)});
        return;
    }
    const modbusrtu::Reply &r = *decoded.value;
    if (r.isException) {
        const int code = r.exceptionCode;
        // servo-modbus: exception 0x04, the seed's only one, is also the drive's answer to a
        // request that reached it damaged (bad CRC; docs/protocols/servo-modbus.md,
        // "Exceptions"): it takes one of the request's retries, like a garbled reply.
        const int allowed = 1 + (s.retries >= 0 ? s.retries : m_serial->settings().retries);
        if (code == m_retriedExceptionCode && attempts < allowed) {
            SerialRequest again = s;
            again.retries = allowed - attempts - 1;
            inner->deleteLater();
            transmit(outer, again, pdu, attempts);
            return;
        }
        QString text = tr("The drive at address %1 rejected the request (Modbus exception %2: %3).")
                           .arg(pdu.address)
                           .arg(hexText(code, 2))
                           .arg(modbusrtu::exceptionCodeName(quint8(code)));
        if (quint8(frame.at(0)) != pdu.address)
            text = tr("The drive at address %1 rejected the request (Modbus exception %2: %3; the reply "
                      "carried address byte %4).")
                       .arg(pdu.address)
                       .arg(hexText(code, 2))
                       .arg(modbusrtu::exceptionCodeName(quint8(code)))
                       .arg(hexText(quint8(frame.at(0)), 2));
        outer->finishWithError({ErrorCode::DriveException, text, code});
        return;
    }
    QList<quint16> registers;
    switch (r.function) {
    case modbusrtu::ReadHoldingRegisters: registers = r.values; break;
    case modbusrtu::WriteSingleRegister: registers = {r.start, r.values.value(0)}; break;
    default: registers = {r.start, r.count}; break;
    }
    outer->finishWithRegisters(registers);
}

void ModbusLink::cancelAll(const Error &why)
{
    m_serial->cancelAll(why);
}

bool ModbusLink::isIdle() const
{
    return m_serial->isIdle();
}
int ModbusLink::queuedCount() const
{
    return m_serial->queuedCount();
}
quint64 ModbusLink::timeoutCount() const
{
    return m_serial->timeoutCount();
}
quint64 ModbusLink::retryCount() const
{
    return m_serial->retryCount();
}
quint64 ModbusLink::checksumErrorCount() const
{
    return m_serial->checksumErrorCount();
}
quint64 ModbusLink::lateReplyCount() const
{
    return m_serial->staleReplyCount();
}
qint64 ModbusLink::wireTimeUs(qsizetype bytes) const
{
    return m_serial->wireTimeUs(bytes);
}

int ModbusLink::defaultTimeoutMs(const modbusrtu::Request &pdu) const
{
    const int replyBytes = std::max(modbusrtu::ExceptionReplySize, modbusrtu::expectedReplySize(pdu));
    const qint64 wire = wireTimeUs(requestBytes(pdu)) + wireTimeUs(replyBytes);
    return int((wire + 999) / 1000) + settings().responseTimeoutMs;
}

qint64 ModbusLink::interFrameGapUs() const
{
    return m_serial->interFrameGapUs();
}

qint64 ModbusLink::interFrameGapUs(qint32 baud, int bitsPerChar)
{
    // Modbus over serial line 1.02, 2.5.1.1: 3.5 characters; above 19200 baud a fixed 1750 us.
    if (baud > 19200 || baud <= 0)
        return 1750;
    return sameDriveGapUs(baud, bitsPerChar); // the same below 19200 baud
}

qint64 ModbusLink::sameDriveGapUs() const
{
    return m_serial->samePeerGapUs();
}

qint64 ModbusLink::sameDriveGapUs(qint32 baud, int bitsPerChar)
{
    // 3.5 characters at every baud rate: the frame separation itself, without the fixed
    // 1750 us the spec recommends above 19200 baud (docs/reliability.md).
    if (baud <= 0)
        return 1750;
    return qint64(std::ceil(WireTime::modbusSameDriveSilenceUs(baud, bitsPerChar)));
}

} // namespace dd
