#include "core/link/modbuslinkprivate.h"

#include "core/common/timerslack.h"
#include "core/link/serialaccess.h"
#include "core/link/traffictap.h"
#include "core/link/urgentqueue.h"
#include "core/protocol/modbus/crc16.h"

#include <QLoggingCategory>
#include <QModbusReply>
#include <QModbusRtuSerialClient>
#include <QSerialPort>
#include <QVariant>
#include <cmath>

#ifdef Q_OS_UNIX
#include <unistd.h>
#endif

Q_LOGGING_CATEGORY(lcModbusLink, "drivedesk.link.modbus")

// How QModbusRtuSerialClient (Qt 6.4.2) behaves, measured on a pty:
//  - setTimeout() ignores values below 10 ms; the response timer starts at bytesWritten.
//  - interFrameDelay() is in microseconds: 2000 at >= 19200 baud, 5000 at 9600 (Qt counts
//    11 bits per character); it never shrinks on reconnect unless setInterFrameDelay(-1).
//  - Before every request (a QTimer of interFrameDelay) it clears its buffer and the port.
//  - A reply is matched by address and function only; a CRC-valid frame from another
//    address is dropped with intermediate error ResponseRequestMismatch, a bad CRC gives
//    ResponseCrcError, and in both cases the request keeps waiting for its timeout. Its
//    framing does not resynchronise: noise before a reply makes the request time out.
//  - Serial port errors become errorOccurred(); the client's state stays ConnectedState.
//  - A broadcast (address 0) finishes when the bytes are written.

namespace dd {

namespace {
// The bytes the port's driver holds that Qt has not read yet (Unix: the port is
// non-blocking; elsewhere nothing).
QByteArray readUnread(QSerialPort *port)
{
    QByteArray out;
#ifdef Q_OS_UNIX
    char buf[256];
    for (int i = 0; i < 16 && port->handle() >= 0; ++i) {
        const ssize_t n = ::read(port->handle(), buf, sizeof buf);
        if (n <= 0)
            break;
        out.append(buf, qsizetype(n));
    }
#else
    Q_UNUSED(port);
#endif
    return out;
}

constexpr int QtMinTimeoutMs = 10; // QModbusClient::setTimeout ignores less
constexpr int WatchdogMs = 250;    // Qt's timer is the primary one above 10 ms
constexpr qsizetype MaxSniffedBytes = 1024;

QString hexByte(int v)
{
    return QStringLiteral("0x%1").arg(v, 2, 16, QLatin1Char('0'));
}
} // namespace

ModbusLink::Private::Private(ModbusLink *link)
    : QObject(link)
    , q(link)
    , m_sniffer(this)
    , m_gapTimer(this)
    , m_abortTimer(this)
{
    m_gapTimer.setSingleShot(true);
    m_gapTimer.setTimerType(Qt::PreciseTimer);
    m_abortTimer.setSingleShot(true);
    m_abortTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_gapTimer, &QTimer::timeout, this, &Private::scheduleNext);
    connect(&m_abortTimer, &QTimer::timeout, this, &Private::onAbortTimer);
    connect(&m_sniffer, &SerialReadSniffer::bytesRead, this, &Private::onSniffed);
    m_clock.start();
}

ModbusLink::Private::~Private() = default;

bool ModbusLink::Private::open(const SerialSettings &settings, Error *error)
{
    if (m_client)
        close({ErrorCode::Cancelled, ModbusLink::tr("The Modbus link was reopened.")});
    m_settings = settings;
    auto *client = new QModbusRtuSerialClient(this);
    client->setConnectionParameter(QModbusDevice::SerialPortNameParameter, settings.portName);
    client->setConnectionParameter(QModbusDevice::SerialBaudRateParameter, settings.baud);
    client->setConnectionParameter(QModbusDevice::SerialDataBitsParameter, settings.dataBits);
    client->setConnectionParameter(QModbusDevice::SerialParityParameter, settings.parity);
    client->setConnectionParameter(QModbusDevice::SerialStopBitsParameter, settings.stopBits);
    client->setNumberOfRetries(0);  // retries are ours: they must wait for a quiet line
    client->setInterFrameDelay(-1); // recompute for this baud (never shrinks otherwise)
    if (!client->connectDevice()) {
        Error e{ErrorCode::OpenFailed,
                ModbusLink::tr("Cannot open serial port %1: %2. Check the device name, that "
                               "no other program is using it, and that you may access it "
                               "(dialout group).")
                    .arg(settings.portName, client->errorString())};
        if (const auto denied = serialAccessProblem(settings.portName))
            e.message = denied->message();
        delete client;
        if (error)
            *error = e;
        return false;
    }
    m_client = client;
    tightenTimerSlack(); // Qt's 2 ms inter-frame delay is on every transaction's path
    connect(m_client, &QModbusDevice::errorOccurred, this, &Private::onClientError, Qt::QueuedConnection);
    if (QIODevice *dev = m_client->device()) {
        connect(dev, &QIODevice::readyRead, this, &Private::onDeviceReadyRead);
        connect(dev, &QIODevice::bytesWritten, this, &Private::onBytesWritten);
    }
    m_sniffer.attach(m_client->device());
    m_taintedUntilUs.clear();
    m_owed.clear();
    m_quietUntilUs = 0;
    m_lastCommandEndUs = 0;
    m_state = State::Idle;
    qCDebug(lcModbusLink) << "opened" << settings.portName << settings.baud << "inter-frame delay us"
                          << m_client->interFrameDelay() << "raw bytes visible" << m_sniffer.isActive();
    return true;
}

void ModbusLink::Private::close(const Error &why)
{
    failAll(why, false);
    m_sniffer.detach();
    if (m_client) {
        QObject::disconnect(m_client, nullptr, this, nullptr);
        if (QIODevice *dev = m_client->device())
            QObject::disconnect(dev, nullptr, this, nullptr);
        m_client->disconnectDevice();
        m_client->deleteLater();
        m_client = nullptr;
    }
    m_state = State::Idle;
}

bool ModbusLink::Private::isOpen() const
{
    return m_client && m_client->state() == QModbusDevice::ConnectedState;
}

bool ModbusLink::Private::reconnect(Error *error)
{
    if (!m_client)
        return false;
    m_sniffer.detach();
    if (m_qtReply) {
        QObject::disconnect(m_qtReply, nullptr, this, nullptr);
        m_qtReply->deleteLater();
        m_qtReply = nullptr;
    }
    m_aborting = true;
    const qint64 t0 = nowUs();
    m_client->disconnectDevice(); // ends Qt's wait (its queue holds only our request)
    m_client->setInterFrameDelay(-1);
    const bool ok = m_client->connectDevice();
    m_aborting = false;
    ++m_reconnects;
    m_reconnectCostUs = (3 * m_reconnectCostUs + (nowUs() - t0)) / 4;
    if (!ok) {
        if (error)
            *error = {ErrorCode::LinkClosed,
                      ModbusLink::tr("The serial port %1 could not be reopened: %2. Was the "
                                     "adapter unplugged?")
                          .arg(m_settings.portName, m_client->errorString())};
        return false;
    }
    m_sniffer.attach(m_client->device());
    return true;
}

LinkReply *ModbusLink::Private::enqueue(const ModbusRequest &request)
{
    auto *reply = new LinkReply(q);
    if (!isOpen()) {
        reply->finishWithError({ErrorCode::LinkClosed, ModbusLink::tr("The serial port is not open.")});
        return reply;
    }
    ModbusRequest r = request;
    const quint8 fc = r.pdu.function;
    if (fc == modbusrtu::WriteMultipleRegisters)
        r.pdu.count = static_cast<quint16>(r.pdu.values.size());
    else if (fc == modbusrtu::WriteSingleRegister)
        r.pdu.count = 1;
    const bool valid = (fc == modbusrtu::ReadHoldingRegisters && r.pdu.address != 0)
        || (fc == modbusrtu::WriteSingleRegister && r.pdu.values.size() == 1)
        || fc == modbusrtu::WriteMultipleRegisters;
    if (!valid || r.pdu.address > 247 || modbusrtu::encodeRequest(r.pdu).isEmpty()) {
        reply->finishWithError({ErrorCode::InvalidArgument,
                                ModbusLink::tr("Invalid Modbus request (function %1, address %2, "
                                               "%3 registers): nothing was sent.")
                                    .arg(hexByte(fc))
                                    .arg(r.pdu.address)
                                    .arg(fc == modbusrtu::ReadHoldingRegisters ? r.pdu.count : r.pdu.values.size())});
        return reply;
    }
    enqueueByUrgency(m_queue, Pending{r, reply, 0});
    if (m_state == State::Idle)
        scheduleNext();
    return reply;
}

void ModbusLink::Private::failAll(const Error &why, bool abortQt)
{
    m_gapTimer.stop();
    m_abortTimer.stop();
    if (m_current) {
        if (m_state == State::Awaiting) {
            const int addr = m_current->request.pdu.address;
            m_owed.insert(addr); // aborted in flight: its answer may still come
            const int quiet = quietAfterTimeoutMs(effectiveTimeoutMs(m_current->request));
            taint(addr, nowUs() + qint64(quiet) * 1000);
            if (abortQt && isOpen()) {
                Error e;
                if (!reconnect(&e))
                    qCWarning(lcModbusLink) << e.message;
            }
        }
        if (m_current->reply)
            m_current->reply->finishWithError(why);
        m_current.reset();
    }
    while (!m_queue.isEmpty()) {
        Pending p = m_queue.dequeue();
        if (p.reply)
            p.reply->finishWithError(why);
    }
    if (m_qtReply) {
        QObject::disconnect(m_qtReply, nullptr, this, nullptr);
        m_qtReply->deleteLater();
        m_qtReply = nullptr;
    }
    m_state = State::Idle;
}

qint64 ModbusLink::Private::wireTimeUs(qsizetype bytes) const
{
    const double baud = m_settings.baud > 0 ? m_settings.baud : 9600;
    return static_cast<qint64>(std::ceil(double(bytes) * m_settings.bitsPerChar * 1e6 / baud));
}

int ModbusLink::Private::effectiveTimeoutMs(const ModbusRequest &r) const
{
    if (r.timeoutMs >= 0)
        return r.timeoutMs;
    const qsizetype requestBytes = r.pdu.function == modbusrtu::WriteMultipleRegisters ? 9 + 2 * r.pdu.values.size()
                                                                                       : 8;
    const int replyBytes = std::max(modbusrtu::ExceptionReplySize, modbusrtu::expectedReplySize(r.pdu));
    const qint64 wire = wireTimeUs(requestBytes) + wireTimeUs(replyBytes);
    return int((wire + 999) / 1000) + m_settings.responseTimeoutMs;
}

int ModbusLink::Private::quietAfterTimeoutMs(int timeoutMs) const
{
    return std::max(2 * timeoutMs, 20);
}

int ModbusLink::Private::silenceMs() const
{
    // Modbus ends a frame after 3.5 quiet characters; a USB adapter delivers in bursts.
    return std::max(5, int((wireTimeUs(4) + 999) / 1000) + 2);
}

void ModbusLink::Private::taint(int address, qint64 untilUs)
{
    auto bump = [this, untilUs](int a) {
        qint64 &t = m_taintedUntilUs[a];
        t = std::max(t, untilUs);
    };
    bump(address);
    // Exception replies of the servo-modbus drive carry address 0x01 whatever the drive's
    // address: a late one would be matched to a request to address 1.
    if (address != 1)
        bump(1);
}

qint64 ModbusLink::Private::cleanAtUs(int address) const
{
    return m_taintedUntilUs.value(address, 0);
}

void ModbusLink::Private::scheduleNext()
{
    if (m_state == State::Awaiting || !m_client)
        return;
    if (!m_current) {
        while (!m_queue.isEmpty() && !m_queue.head().reply)
            m_queue.dequeue();
        if (m_queue.isEmpty()) {
            m_state = State::Idle;
            emit q->idle();
            return;
        }
    }
    const Pending &next = m_current ? *m_current : m_queue.head();
    qint64 readyAt = std::max(
        {m_lastFinishUs + qint64(m_settings.minGapMs) * 1000, m_quietUntilUs, cleanAtUs(next.request.pdu.address)});
    if (m_settings.minCommandSpacingMs > 0 && m_lastCommandEndUs > 0 && m_client) {
        // The drive counts from the last byte of each command; Qt writes ours after its
        // inter-frame delay. 2 ms for timer and adapter jitter.
        const qint64 nextEnd = m_lastCommandEndUs + qint64(m_settings.minCommandSpacingMs) * 1000 + 2000;
        const qint64 lead = m_client->interFrameDelay() + wireTimeUs(modbusrtu::encodeRequest(next.request.pdu).size());
        readyAt = std::max(readyAt, nextEnd - lead);
    }
    const qint64 now = nowUs();
    if (now < readyAt) {
        m_state = State::Waiting;
        m_gapTimer.start(int((readyAt - now + 999) / 1000));
        return;
    }
    if (!m_current)
        m_current = m_queue.dequeue();
    transmit();
}

void ModbusLink::Private::transmit()
{
    Pending &p = *m_current;
    ++p.attempts;
    m_rxSinceSend.clear();
    m_writtenUs = 0;
    m_lastRxUs = 0;
    m_mismatchSeen = false;
    m_crcErrorSeen = false;
    const modbusrtu::Request &pdu = p.request.pdu;
    const QByteArray adu = modbusrtu::encodeRequest(pdu);
    const int timeout = effectiveTimeoutMs(p.request);
    m_client->setTimeout(std::max(QtMinTimeoutMs, timeout));
    const int ifdUs = m_client->interFrameDelay();
    m_sentLowerBoundUs = nowUs() + ifdUs;
    const QModbusRequest qreq(QModbusPdu::FunctionCode(pdu.function), adu.mid(2, adu.size() - 4));
    // Nothing is pending: whatever waits unread answers no request of ours (a duplicate, a
    // late answer). Read after the request went out it would pass for its answer.
    if (auto *port = qobject_cast<QSerialPort *>(m_client->device())) {
        // What the port holds unread came while nothing was pending (a late answer that
        // landed while the client reconnected): shown as stray before it is flushed, so
        // that a scan still asks that address again.
        const QByteArray unread = readUnread(port);
        if (!unread.isEmpty()) {
            recordDiscarded(unread, QStringLiteral("late or unsolicited bytes (no request pending)"));
            if (unread.size() >= 4 && hasValidCrc16(unread))
                m_owed.remove(quint8(unread.at(0)));
            ++m_strayBursts;
            reportStray(unread);
        }
        port->clear(QSerialPort::Input);
    }
    QModbusReply *r = m_client->sendRawRequest(qreq, pdu.address);
    if (!r) {
        finishCurrent({ErrorCode::LinkClosed,
                       ModbusLink::tr("The Modbus client refused the request: %1").arg(m_client->errorString())});
        return;
    }
    m_qtReply = r;
    m_state = State::Awaiting;
    QString note = p.request.note;
    if (p.attempts > 1)
        note = QStringLiteral("%1 (retry %2)").arg(note).arg(p.attempts - 1).trimmed();
    recordTx(adu, note);
    QPointer<QModbusReply> guard(r);
    connect(
        r, &QModbusReply::finished, this,
        [this, guard] {
            if (guard)
                onQtFinished(guard);
        },
        Qt::QueuedConnection);
    connect(
        r, &QModbusReply::intermediateErrorOccurred, this,
        [this, guard](QModbusDevice::IntermediateError e) {
            if (guard)
                onQtIntermediateError(guard, e);
        },
        Qt::QueuedConnection);
    // Qt's response timer starts when the bytes are written, after its inter-frame delay.
    const int ifdMs = (ifdUs + 999) / 1000;
    // Below Qt's 10 ms minimum our own timer ends the wait by reconnecting the client, when
    // that is quicker than letting Qt's timer run (the reconnect cost is measured).
    const int reconnectMs = int((m_reconnectCostUs + 999) / 1000);
    const bool ownTimer = timeout + reconnectMs < QtMinTimeoutMs;
    m_abortTimer.start(timeout + ifdMs + (ownTimer ? 0 : WatchdogMs));
}

void ModbusLink::Private::onClientError(QModbusDevice::Error error)
{
    if (m_aborting || !m_client)
        return;
    switch (error) {
    case QModbusDevice::ConnectionError:
    case QModbusDevice::ReadError:
    case QModbusDevice::WriteError: {
        const Error e{ErrorCode::LinkClosed,
                      ModbusLink::tr("The serial port %1 failed (%2). Was the adapter unplugged?")
                          .arg(m_settings.portName, m_client->errorString())};
        qCWarning(lcModbusLink) << e.message;
        close(e);
        emit q->closed(e);
        break;
    }
    default: qCDebug(lcModbusLink) << "Modbus client note:" << error << m_client->errorString(); break;
    }
}

void ModbusLink::Private::onSniffed(const QByteArray &bytes)
{
    // Called from inside the port's read handling: only record.
    // Bytes that come while Qt still holds the request back (its inter-frame delay) answer
    // no request of ours: Qt would match a duplicated or late reply of the same shape to
    // the request it has not even sent (seen under load: PA19 read as PA18's second copy).
    if (m_state == State::Awaiting && m_writtenUs > 0) {
        m_lastRxUs = nowUs();
        m_rxSinceSend += bytes;
        if (m_rxSinceSend.size() > MaxSniffedBytes)
            m_rxSinceSend.remove(0, m_rxSinceSend.size() - MaxSniffedBytes);
        return;
    }
    recordDiscarded(bytes, QStringLiteral("late or unsolicited bytes (no request pending)"));
    // A late answer that lands while nothing waits pays its address's debt.
    if (bytes.size() >= 4 && hasValidCrc16(bytes))
        m_owed.remove(quint8(bytes.at(0)));
    ++m_strayBursts;
    noteStrayActivity();
    reportStray(bytes);
}

void ModbusLink::Private::onBytesWritten()
{
    // Qt writes only the request it was handed: this is when it reached the port.
    if (m_state == State::Awaiting && m_writtenUs == 0) {
        m_writtenUs = nowUs();
        if (m_current)
            m_lastCommandEndUs = m_writtenUs + wireTimeUs(modbusrtu::encodeRequest(m_current->request.pdu).size());
    }
}

void ModbusLink::Private::reportStray(const QByteArray &bytes)
{
    // From the event loop: the sniffer calls us from inside the port's read handling, and a
    // receiver may send the next request.
    QMetaObject::invokeMethod(
        q, [link = q, bytes] { emit link->strayBytes(bytes); }, Qt::QueuedConnection);
}

void ModbusLink::Private::onDeviceReadyRead()
{
    // Without the sniffer this is the only sign of stray bytes (Qt has read them already).
    if (m_sniffer.isActive() || m_state == State::Awaiting)
        return;
    ++m_strayBursts;
    noteStrayActivity();
}

void ModbusLink::Private::noteStrayActivity()
{
    // Someone is still talking: nothing goes out before the line is quiet, and addresses
    // waiting for a late reply wait a little longer.
    const qint64 until = nowUs() + qint64(silenceMs()) * 1000;
    m_quietUntilUs = std::max(m_quietUntilUs, until);
    const qint64 now = nowUs();
    for (auto it = m_taintedUntilUs.begin(); it != m_taintedUntilUs.end(); ++it) {
        if (it.value() > now)
            it.value() = std::max(it.value(), until);
    }
}

void ModbusLink::Private::recordTx(const QByteArray &adu, const QString &note)
{
    if (m_tap)
        m_tap->recordSerial(TrafficRecord::Direction::Tx, m_settings.portName, adu, note);
}

void ModbusLink::Private::recordRx(const QByteArray &adu, const QString &note)
{
    if (m_tap)
        m_tap->recordSerial(TrafficRecord::Direction::Rx, m_settings.portName, adu, note);
}

void ModbusLink::Private::recordDiscarded(const QByteArray &bytes, const QString &note)
{
    if (m_tap)
        m_tap->recordSerial(TrafficRecord::Direction::Discarded, m_settings.portName, bytes, note);
}

} // namespace dd
