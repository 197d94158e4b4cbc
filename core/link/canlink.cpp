#include "core/link/canlink.h"

#include "core/link/traffictap.h"
#include "core/link/urgentqueue.h"

#include <QCanBus>
#include <QCanBusFrame>
#include <QLoggingCategory>
#include <QTcpSocket>
#include <QVariant>

Q_LOGGING_CATEGORY(lcCanLink, "drivedesk.link.can")

namespace dd {

CanLink::CanLink(QObject *parent)
    : QObject(parent)
    , m_timer(this)
{
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &CanLink::onTick);
    m_clock.start();
}

CanLink::~CanLink()
{
    m_closing = true;
    failAll({ErrorCode::Cancelled, tr("The CAN link was destroyed.")});
    if (m_device) {
        m_device->disconnect(this);
        m_device->disconnectDevice();
        delete m_device;
    }
}

bool CanLink::open(const CanSettings &settings, Error *error)
{
    if (m_device)
        close();
    m_settings = settings;
    QString why;
    QCanBusDevice *device = QCanBus::instance()->createDevice(settings.plugin, settings.interface, &why);
    if (!device) {
        const Error e{ErrorCode::OpenFailed,
                      tr("Cannot create CAN device %1:%2: %3. Available plugins: %4.")
                          .arg(settings.plugin, settings.interface, why,
                               QCanBus::instance()->plugins().join(QStringLiteral(", ")))};
        if (error)
            *error = e;
        return false;
    }
    if (settings.configureBitrate)
        device->setConfigurationParameter(QCanBusDevice::BitRateKey, QVariant(settings.bitrate));
    else if (settings.plugin == QLatin1String("socketcan"))
        device->setConfigurationParameter(QCanBusDevice::BitRateKey, QVariant());
    device->setParent(this);
    m_device = device;
    m_closing = false;
    connect(device, &QCanBusDevice::stateChanged, this, &CanLink::onStateChanged);
    connect(device, &QCanBusDevice::errorOccurred, this, &CanLink::onErrorOccurred);
    connect(device, &QCanBusDevice::framesReceived, this, &CanLink::onFramesReceived);
    if (!device->connectDevice()) {
        const Error e{ErrorCode::OpenFailed,
                      tr("Cannot connect to CAN interface %1: %2. Is the interface up "
                         "(ip link set %3 up type can bitrate %4)?")
                          .arg(settings.toString(), device->errorString(), settings.interface)
                          .arg(settings.bitrate)};
        device->disconnect(this);
        delete device;
        m_device = nullptr;
        if (error)
            *error = e;
        return false;
    }
    return true;
}

void CanLink::close()
{
    if (!m_device)
        return;
    m_closing = true;
    failAll({ErrorCode::Cancelled, tr("The CAN link %1 was closed.").arg(m_settings.toString())});
    m_device->disconnect(this);
    m_device->disconnectDevice();
    m_device->deleteLater();
    m_device = nullptr;
    m_unsent.clear();
    emit closed(Error::none());
}

bool CanLink::isConnected() const
{
    return m_device && m_device->state() == QCanBusDevice::ConnectedState;
}

bool CanLink::send(const CanFrameData &frame, const QString &note)
{
    if (!m_device)
        return false;
    if (!isConnected()) {
        m_unsent.enqueue({frame, note});
        return true;
    }
    return writeNow(frame, note);
}

LinkReply *CanLink::request(const CanRequest &request)
{
    auto *reply = new LinkReply(this);
    if (!m_device) {
        reply->finishWithError({ErrorCode::LinkClosed, tr("The CAN link is not open.")});
        return reply;
    }
    enqueueByUrgency(m_waiting, Pending{request, reply, 0, 0, 0});
    pump();
    return reply;
}

void CanLink::cancelAll(const Error &why)
{
    failAll(why);
}

void CanLink::failAll(const Error &why)
{
    for (Pending &p : m_inFlight)
        if (p.reply)
            p.reply->finishWithError(why);
    m_inFlight.clear();
    while (!m_waiting.isEmpty()) {
        Pending p = m_waiting.dequeue();
        if (p.reply)
            p.reply->finishWithError(why);
    }
    m_timer.stop();
}

bool CanLink::writeNow(const CanFrameData &frame, const QString &note)
{
    QCanBusFrame f(frame.id, frame.data);
    f.setExtendedFrameFormat(frame.extended);
    if (!m_device->writeFrame(f)) {
        qCWarning(lcCanLink) << "write failed" << m_device->errorString();
        return false;
    }
    if (m_tap)
        m_tap->recordCan(TrafficRecord::Direction::Tx, m_settings.toString(), frame, note);
    return true;
}

void CanLink::pump()
{
    if (!isConnected())
        return;
    auto fitsWindow = [this] {
        const CanRequest &next = m_waiting.head().request;
        // An urgent frame that expects no reply does not wait for the window.
        return m_inFlight.size() < m_settings.maxInFlight || (next.urgent && !next.matcher);
    };
    while (!m_waiting.isEmpty() && fitsWindow()) {
        Pending p = m_waiting.dequeue();
        if (!p.reply)
            continue;
        ++p.attempts;
        if (!writeNow(p.request.frame, p.request.note)) {
            p.reply->finishWithError(
                {ErrorCode::LinkClosed,
                 tr("Cannot write to CAN interface %1: %2").arg(m_settings.toString(), m_device->errorString())});
            continue;
        }
        if (!p.request.matcher) {
            p.reply->setAttempts(p.attempts);
            p.reply->finishEmpty();
            continue;
        }
        const int timeout = p.request.timeoutMs >= 0 ? p.request.timeoutMs : m_settings.responseTimeoutMs;
        p.sentUs = nowUs();
        p.deadlineUs = p.sentUs + qint64(timeout) * 1000;
        m_inFlight.append(p);
    }
    armTimer();
}

void CanLink::armTimer()
{
    if (m_inFlight.isEmpty()) {
        m_timer.stop();
        return;
    }
    qint64 earliest = m_inFlight.first().deadlineUs;
    for (const Pending &p : m_inFlight)
        earliest = std::min(earliest, p.deadlineUs);
    const qint64 waitMs = std::max<qint64>(0, (earliest - nowUs() + 999) / 1000);
    m_timer.start(static_cast<int>(waitMs));
}

void CanLink::onTick()
{
    const qint64 now = nowUs();
    for (int i = 0; i < m_inFlight.size();) {
        Pending &p = m_inFlight[i];
        if (!p.reply) {
            m_inFlight.removeAt(i);
            continue;
        }
        if (p.deadlineUs > now) {
            ++i;
            continue;
        }
        ++m_timeouts;
        const int retries = p.request.retries >= 0 ? p.request.retries : m_settings.retries;
        const int timeout = p.request.timeoutMs >= 0 ? p.request.timeoutMs : m_settings.responseTimeoutMs;
        if (p.attempts <= retries) {
            ++m_retryCount;
            ++p.attempts;
            writeNow(p.request.frame,
                     QStringLiteral("%1 (retry %2)").arg(p.request.note).arg(p.attempts - 1).trimmed());
            p.sentUs = now;
            p.deadlineUs = now + qint64(timeout) * 1000;
            ++i;
            continue;
        }
        p.reply->setAttempts(p.attempts);
        p.reply->finishWithError({ErrorCode::Timeout,
                                  tr("No reply on %1 within %2 ms after %3 attempts. Check the "
                                     "station number, the bitrate and the bus termination.")
                                      .arg(m_settings.toString())
                                      .arg(timeout)
                                      .arg(p.attempts)});
        m_inFlight.removeAt(i);
    }
    pump();
}

void CanLink::onFramesReceived()
{
    if (!m_device)
        return;
    const QList<QCanBusFrame> frames = m_device->readAllFrames();
    for (const QCanBusFrame &f : frames) {
        if (!f.isValid() || f.frameType() != QCanBusFrame::DataFrame || f.hasLocalEcho())
            continue;
        CanFrameData frame{f.frameId(), f.payload(), f.hasExtendedFrameFormat()};
        if (m_tap)
            m_tap->recordCan(TrafficRecord::Direction::Rx, m_settings.toString(), frame);
        for (int i = 0; i < m_inFlight.size(); ++i) {
            Pending &p = m_inFlight[i];
            if (p.reply && p.request.matcher && p.request.matcher(frame)) {
                p.reply->setAttempts(p.attempts);
                p.reply->setRoundTripUs(nowUs() - p.sentUs);
                p.reply->finishWithCanFrame(frame);
                m_inFlight.removeAt(i);
                break;
            }
        }
        emit frameReceived(frame);
    }
    pump();
}

void CanLink::onStateChanged(QCanBusDevice::CanBusDeviceState state)
{
    if (state == QCanBusDevice::ConnectedState) {
        if (m_settings.plugin == QLatin1String("virtualcan")) {
            // Qt's virtualcan leaves Nagle's algorithm on its TCP socket: a frame written
            // while the previous one is unacknowledged waits for the peer's delayed ACK
            // (~40 ms on Linux), which stalls pipelined requests into timeouts.
            for (QTcpSocket *socket : m_device->findChildren<QTcpSocket *>())
                socket->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        }
        while (!m_unsent.isEmpty()) {
            const auto item = m_unsent.dequeue();
            writeNow(item.first, item.second);
        }
        emit connected();
        pump();
    } else if (state == QCanBusDevice::UnconnectedState && !m_closing) {
        const Error e{ErrorCode::LinkClosed,
                      tr("The CAN bus %1 went away. Check the adapter and the bus.").arg(m_settings.toString())};
        failAll(e);
        if (m_device) {
            m_device->disconnect(this);
            m_device->deleteLater();
            m_device = nullptr;
        }
        emit closed(e);
    }
}

void CanLink::onErrorOccurred(QCanBusDevice::CanBusError error)
{
    if (!m_device)
        return;
    qCWarning(lcCanLink) << "CAN error" << error << m_device->errorString();
    if (error == QCanBusDevice::ConnectionError && m_device->state() != QCanBusDevice::ConnectedState && !m_closing) {
        const Error e{ErrorCode::LinkClosed,
                      tr("CAN interface %1: %2").arg(m_settings.toString(), m_device->errorString())};
        failAll(e);
        m_device->disconnect(this);
        m_device->deleteLater();
        m_device = nullptr;
        emit closed(e);
    }
}

} // namespace dd
