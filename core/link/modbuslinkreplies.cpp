#include "core/link/modbuslinkprivate.h"

#include "core/protocol/modbus/crc16.h"

#include <QModbusReply>
#include <QModbusRtuSerialClient>

// ModbusLink::Private, second half: what happens when Qt reports on a request.

namespace dd {

namespace {
constexpr int BroadcastTurnaroundMs = 100; // Modbus: let servers act on a broadcast

QByteArray aduOf(int address, const QModbusResponse &pdu)
{
    QByteArray a;
    a.append(static_cast<char>(address));
    a.append(static_cast<char>(quint8(pdu.functionCode()) | (pdu.isException() ? 0x80 : 0x00)));
    a += pdu.data();
    return withCrc16(a);
}

QString hexByte(int v)
{
    return QStringLiteral("0x%1").arg(v, 2, 16, QLatin1Char('0'));
}
} // namespace

void ModbusLink::Private::onQtFinished(QModbusReply *reply)
{
    if (reply != m_qtReply || m_state != State::Awaiting || !m_current) {
        reply->deleteLater();
        return;
    }
    m_abortTimer.stop();
    m_qtReply = nullptr;
    const QModbusDevice::Error err = reply->error();
    const QModbusResponse response = reply->rawResult();
    const QString qtText = reply->errorString();
    reply->deleteLater();
    const modbusrtu::Request &pdu = m_current->request.pdu;

    if (pdu.address == modbusrtu::BroadcastAddress) {
        m_quietUntilUs = std::max(m_quietUntilUs, nowUs() + qint64(BroadcastTurnaroundMs) * 1000);
        if (err == QModbusDevice::NoError)
            finishCurrent(Error::none());
        else
            finishCurrent(
                {ErrorCode::LinkClosed,
                 ModbusLink::tr("The broadcast could not be sent on %1: %2").arg(m_settings.portName, qtText)});
        return;
    }
    switch (err) {
    case QModbusDevice::NoError: handleSuccess(response); return;
    case QModbusDevice::ProtocolError: {
        // Qt 6.4 keeps an exception reply's function code sign-extended (0xFFFFFF83) in an
        // enum that cannot hold it, so QModbusPdu's inline accessors (isException(),
        // exceptionCode()) read an invalid enum value: undefined behaviour, found by UBSan.
        // Where the raw bytes are visible the exception is read from them instead.
        QByteArray adu;
        if (m_sniffer.isActive())
            adu = exceptionInSniffedBytes();
        else if (response.isException())
            adu = aduOf(pdu.address, response);
        if (!adu.isEmpty()) {
            const int code = quint8(adu.at(2));
            recordRx(adu, QStringLiteral("exception %1").arg(modbusrtu::exceptionCodeName(quint8(code))));
            Error e{ErrorCode::DriveException,
                    ModbusLink::tr("The drive at address %1 rejected the request (Modbus exception "
                                   "%2: %3).")
                        .arg(pdu.address)
                        .arg(hexByte(code))
                        .arg(modbusrtu::exceptionCodeName(quint8(code))),
                    code};
            finishException(e);
            return;
        }
        break;
    }
    case QModbusDevice::TimeoutError: handleTimeout(effectiveTimeoutMs(m_current->request)); return;
    default: break;
    }
    taint(pdu.address, nowUs() + qint64(silenceMs()) * 1000);
    retryOrFail({ErrorCode::Malformed,
                 ModbusLink::tr("The Modbus request to address %1 on %2 failed: %3")
                     .arg(pdu.address)
                     .arg(m_settings.portName, qtText)},
                silenceMs());
}

void ModbusLink::Private::handleSuccess(const QModbusResponse &response)
{
    const ModbusRequest &req = m_current->request;
    const QByteArray adu = aduOf(req.pdu.address, response);
    const qint64 now = nowUs();
    modbusrtu::DecodeError why = modbusrtu::DecodeError::None;
    const Decoded<modbusrtu::Reply> decoded = modbusrtu::decodeReply(adu, req.pdu, &why);
    if (!decoded.ok()) {
        recordDiscarded(adu, QStringLiteral("reply does not fit the request: %1").arg(decoded.error));
        taint(req.pdu.address, now + qint64(silenceMs()) * 1000);
        retryOrFail({ErrorCode::Malformed,
                     ModbusLink::tr("The reply from address %1 on %2 does not fit the request (%3).")
                         .arg(req.pdu.address)
                         .arg(m_settings.portName, decoded.error)},
                    silenceMs());
        return;
    }
    const qsizetype requestBytes = modbusrtu::encodeRequest(req.pdu).size();
    // From the request reaching the port when that was seen: Qt writes it after its
    // inter-frame delay, or later when the event loop was held up, and a duplicated answer
    // arriving just after that late write must not pass for this one's. Judged by when
    // the reply's bytes came (when seen), not by this later, queued call.
    const qint64 sentUs = std::max(m_sentLowerBoundUs, m_writtenUs);
    const qint64 arrivedUs = m_lastRxUs >= sentUs ? m_lastRxUs : now;
    const qint64 earliest = sentUs + (wireTimeUs(requestBytes) + wireTimeUs(adu.size())) / 2;
    // Qt keeps bytes that followed a reply in its buffer and matches them to the next
    // request of the same shape: a duplicated or late answer then passes for this one's.
    // Where the raw bytes are visible, the answer must be among those read since the request
    // went out (onSniffed); where not, the request must at least have been written.
    const bool stale = m_writtenUs == 0 || (m_sniffer.isActive() && !m_rxSinceSend.contains(adu));
    // The stale-reply rule (docs/reliability.md): a reply sooner than the wire allows is a
    // stale answer only when one is owed, i.e. the last request to this address went
    // unanswered. Dropping it pays that debt: a fast peer (pty, socat, deep-FIFO adapter)
    // costs one attempt at most, and with nothing owed a fast reply is the answer.
    const bool early = arrivedUs < earliest;
    const bool owed = m_owed.contains(req.pdu.address);
    if (stale || (early && owed)) {
        ++m_lateReplies;
        m_owed.remove(req.pdu.address);
        m_current->droppedEarly = !stale;
        const qint64 after = arrivedUs - sentUs;
        const qint64 need = 2 * (earliest - sentUs);
        recordDiscarded(adu,
                        stale ? QStringLiteral("received before the request was written: a stale answer")
                              : QStringLiteral("stale: came %1 us after the request (the wire needs %2 us) "
                                               "while the last request to this address was unanswered")
                                    .arg(after)
                                    .arg(need));
        const int quiet = quietAfterTimeoutMs(effectiveTimeoutMs(req));
        taint(req.pdu.address, now + qint64(quiet) * 1000);
        const QString seen = stale
            ? ModbusLink::tr("A reply from address %1 on %2 reached the port before the request was "
                             "written: a duplicated or late answer to an earlier request, dropped.")
                  .arg(req.pdu.address)
                  .arg(m_settings.portName)
            : ModbusLink::tr("A reply from address %1 on %2 came %3 us after the request, sooner than "
                             "the wire can carry request and reply at %4 baud (%5 us), while the last "
                             "request to that address was still unanswered: it was dropped as that "
                             "request's late answer.")
                  .arg(req.pdu.address)
                  .arg(m_settings.portName)
                  .arg(after)
                  .arg(m_settings.baud)
                  .arg(need);
        retryOrFail({ErrorCode::Timeout,
                     seen + QLatin1Char(' ')
                         + ModbusLink::tr("The next attempt takes a fast reply; if this was the last "
                                          "attempt, raise the retries (--retries).")},
                    quiet);
        return;
    }
    // A drive answers in order: once it answered this request, no earlier answer follows.
    m_owed.remove(req.pdu.address);
    recordRx(adu);
    const modbusrtu::Reply &r = *decoded.value;
    QList<quint16> registers;
    switch (r.function) {
    case modbusrtu::ReadHoldingRegisters: registers = r.values; break;
    case modbusrtu::WriteSingleRegister: registers = {r.start, r.values.value(0)}; break;
    default: registers = {r.start, r.count}; break;
    }
    finishCurrent(Error::none(), registers);
}

void ModbusLink::Private::handleTimeout(int timeoutMs)
{
    ++m_timeouts;
    const int address = m_current->request.pdu.address;
    // Unanswered: its answer may still come and pass for the next one's (the stale-reply
    // rule). Not when a fast reply was dropped as stale meanwhile: that may have been it.
    if (!m_current->droppedEarly)
        m_owed.insert(address);
    const int quiet = quietAfterTimeoutMs(timeoutMs);
    taint(address, nowUs() + qint64(quiet) * 1000);
    if (!m_rxSinceSend.isEmpty()) {
        recordDiscarded(m_rxSinceSend, QStringLiteral("bytes that formed no reply"));
        reportStray(m_rxSinceSend);
    }
    Error e;
    if (m_crcErrorSeen) {
        e = {ErrorCode::ChecksumError,
             ModbusLink::tr("The reply from address %1 on %2 failed its CRC. Check the cable "
                            "shielding, the bus termination and the baud rate.")
                 .arg(address)
                 .arg(m_settings.portName)};
    } else if (!m_mismatchSeen && !m_rxSinceSend.isEmpty()) {
        e = {ErrorCode::Timeout,
             ModbusLink::tr("No complete reply from address %1 on %2 within %3 ms: only %4 "
                            "byte(s) arrived, which form no valid frame (an incomplete or "
                            "garbled reply). Check the baud rate, the wiring and the bus "
                            "termination.")
                 .arg(address)
                 .arg(m_settings.portName)
                 .arg(timeoutMs)
                 .arg(m_rxSinceSend.size())};
    } else {
        e = {ErrorCode::Timeout,
             ModbusLink::tr("No reply from address %1 on %2 within %3 ms. Check the drive address "
                            "(PA51), the baud rate, the wiring (A/B swapped?) and the bus "
                            "termination.")
                 .arg(address)
                 .arg(m_settings.portName)
                 .arg(timeoutMs)};
        const QByteArray stray = strayFrameInSniffedBytes();
        if (m_mismatchSeen && !stray.isEmpty() && quint8(stray.at(0)) == address)
            e.message += QLatin1Char(' ')
                + ModbusLink::tr("A frame with function %1 came from that address instead, "
                                 "which does not answer this request (function %2).")
                      .arg(hexByte(quint8(stray.at(1))), hexByte(m_current->request.pdu.function));
        else if (m_mismatchSeen && !stray.isEmpty())
            e.message += QLatin1Char(' ')
                + ModbusLink::tr("A frame from address %1 arrived instead: do two drives "
                                 "share an address, or does another master talk on the "
                                 "bus?")
                      .arg(quint8(stray.at(0)));
        else if (m_mismatchSeen)
            e.message += QLatin1Char(' ')
                + ModbusLink::tr("A frame with another address arrived meanwhile; servo "
                                 "drives send exception replies with address 1, so the "
                                 "drive may have rejected the request.");
    }
    retryOrFail(e, quiet);
}

QByteArray ModbusLink::Private::strayFrameInSniffedBytes() const
{
    // The first CRC-valid frame among the raw bytes, its length taken from its function code.
    const QByteArray &b = m_rxSinceSend;
    for (qsizetype i = 0; i + 4 <= b.size(); ++i) {
        const quint8 fc = quint8(b.at(i + 1));
        qsizetype n = 0;
        if (fc & modbusrtu::ExceptionFlag)
            n = modbusrtu::ExceptionReplySize;
        else if (fc == 0x05 || fc == 0x06 || fc == 0x0F || fc == 0x10)
            n = 8;
        else if (fc >= 0x01 && fc <= 0x04)
            n = 5 + quint8(b.at(i + 2));
        if (n > 0 && i + n <= b.size() && hasValidCrc16(b.mid(i, n)))
            return b.mid(i, n);
    }
    return {};
}

void ModbusLink::Private::onQtIntermediateError(QModbusReply *reply, QModbusDevice::IntermediateError error)
{
    if (reply != m_qtReply || m_state != State::Awaiting || !m_current)
        return;
    if (error == QModbusDevice::ResponseCrcError) {
        ++m_checksumErrors;
        m_crcErrorSeen = true;
        // Qt's framing is out of step now and would only time out: let the rest of the
        // frame pass, then abort and try again.
        m_abortTimer.start(silenceMs());
        return;
    }
    if (error != QModbusDevice::ResponseRequestMismatch)
        return;
    m_mismatchSeen = true;
    const QByteArray adu = exceptionInSniffedBytes();
    if (adu.isEmpty()) {
        // Someone else's frame (a late reply to an earlier request?): keep waiting.
        if (!m_rxSinceSend.isEmpty())
            reportStray(m_rxSinceSend);
        return;
    }
    const modbusrtu::Request pdu = m_current->request.pdu;
    if (!abortInFlight())
        return;
    const int code = quint8(adu.at(2));
    recordRx(adu,
             QStringLiteral("exception %1 with address byte %2")
                 .arg(modbusrtu::exceptionCodeName(quint8(code)), hexByte(quint8(adu.at(0)))));
    finishException({ErrorCode::DriveException,
                     ModbusLink::tr("The drive at address %1 rejected the request (Modbus exception "
                                    "%2: %3; the reply carried address byte %4).")
                         .arg(pdu.address)
                         .arg(hexByte(code))
                         .arg(modbusrtu::exceptionCodeName(quint8(code)))
                         .arg(hexByte(quint8(adu.at(0)))),
                     code});
}

void ModbusLink::Private::finishException(const Error &error)
{
    // servo-modbus: exception 0x04, the seed's only one, is also a drive's answer to a
    // request that reached it damaged (bad CRC; docs/protocols/servo-modbus.md, "Exceptions"):
    // it takes one of the request's retries, like a garbled reply. Other codes are final.
    if (m_retriedExceptionCode >= 0 && error.driveCode == m_retriedExceptionCode)
        retryOrFail(error, 0);
    else
        finishCurrent(error);
}

QByteArray ModbusLink::Private::exceptionInSniffedBytes() const
{
    const modbusrtu::Request &pdu = m_current->request.pdu;
    const qsizetype n = modbusrtu::ExceptionReplySize;
    for (qsizetype i = 0; i + n <= m_rxSinceSend.size(); ++i) {
        const QByteArray window = m_rxSinceSend.mid(i, n);
        const auto decoded = modbusrtu::decodeReply(window, pdu);
        if (decoded.ok() && decoded.value->isException)
            return window;
    }
    return {};
}

void ModbusLink::Private::onAbortTimer()
{
    if (m_state != State::Awaiting || !m_current)
        return;
    const bool crc = m_crcErrorSeen;
    const int timeout = effectiveTimeoutMs(m_current->request);
    const int address = m_current->request.pdu.address;
    if (!abortInFlight())
        return;
    if (crc) {
        if (!m_rxSinceSend.isEmpty())
            recordDiscarded(m_rxSinceSend, QStringLiteral("bad CRC"));
        taint(address, nowUs() + qint64(silenceMs()) * 1000);
        retryOrFail({ErrorCode::ChecksumError,
                     ModbusLink::tr("The reply from address %1 on %2 failed its CRC. Check the "
                                    "cable shielding, the bus termination and the baud rate.")
                         .arg(address)
                         .arg(m_settings.portName)},
                    silenceMs());
        return;
    }
    handleTimeout(timeout);
}

bool ModbusLink::Private::abortInFlight()
{
    m_abortTimer.stop();
    Error e;
    if (reconnect(&e))
        return true;
    close(e);
    emit q->closed(e);
    return false;
}

void ModbusLink::Private::retryOrFail(const Error &error, int quietMs)
{
    m_abortTimer.stop();
    if (m_qtReply) {
        QObject::disconnect(m_qtReply, nullptr, this, nullptr);
        m_qtReply->deleteLater();
        m_qtReply = nullptr;
    }
    Q_UNUSED(quietMs); // the address is tainted by the caller
    const int retries = m_current->request.retries >= 0 ? m_current->request.retries : m_settings.retries;
    if (m_current->attempts <= retries && m_current->reply) {
        ++m_retries;
        m_state = State::Waiting;
        scheduleNext();
        return;
    }
    finishCurrent(error);
}

void ModbusLink::Private::finishCurrent(const Error &error, const QList<quint16> &registers)
{
    m_abortTimer.stop();
    if (!m_current)
        return;
    Pending p = std::move(*m_current);
    m_current.reset();
    const qint64 now = nowUs();
    if (p.reply) {
        p.reply->setAttempts(p.attempts);
        // From the request reaching the port to the reply's last byte when both were seen,
        // not to this (later, queued) call: the scanner sizes its timeouts from it.
        const bool precise = m_writtenUs > 0 && m_lastRxUs >= m_writtenUs;
        p.reply->setRoundTripUs(precise ? m_lastRxUs - m_writtenUs : now - m_sentLowerBoundUs);
        if (error.isError())
            p.reply->finishWithError(error);
        else
            p.reply->finishWithRegisters(registers);
    }
    m_lastFinishUs = now;
    // The reply began after the drive had the whole command (see SerialLink): anchor the
    // command spacing there, taking the shortest reply Modbus has (5 bytes) to stay safe.
    if (!error.isError() && m_lastRxUs > 0)
        m_lastCommandEndUs = std::max(m_lastCommandEndUs, now - wireTimeUs(5));
    m_state = State::Idle;
    scheduleNext();
}

} // namespace dd
