#include "core/link/canlink.h"

#include "core/link/traffictap.h"
#include "core/link/wiretime.h"

#include <QCanBus>
#include <QCanBusFrame>
#include <QLoggingCategory>
#include <QTcpSocket>
#include <QVariant>

#include <algorithm>
#include <cmath>

Q_LOGGING_CATEGORY(lcCanLink, "drivedesk.link.can")

namespace dd {

namespace {

// Arbitration order: the lower key wins the bus. A standard frame beats an extended one with
// the same 11-bit base identifier (its RTR / IDE bits are dominant where the extended one's
// SRR / IDE are recessive).
quint64 priorityKey(quint32 id, bool extended)
{
    if (!extended)
        return quint64(id & 0x7FF) << 19;
    return (quint64((id >> 18) & 0x7FF) << 19) | (quint64(1) << 18) | (id & 0x3FFFF);
}

quint64 laneKey(const CanFrameData &frame)
{
    return (quint64(frame.extended) << 32) | frame.id;
}

} // namespace

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
    Pending p{request, reply, 0, 0, 0};
    if (request.urgent)
        m_urgent.enqueue(std::move(p));
    else
        laneFor(laneKey(request.frame)).queue.enqueue(std::move(p));
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
    QList<Pending> waiting;
    while (!m_urgent.isEmpty())
        waiting.append(m_urgent.dequeue());
    for (Lane &lane : m_lanes)
        while (!lane.queue.isEmpty())
            waiting.append(lane.queue.dequeue());
    m_lanes.clear();
    m_nextLane = 0;
    for (Pending &p : waiting)
        if (p.reply)
            p.reply->finishWithError(why);
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
    const qint64 now = nowUs();
    m_ownBusEndUs = std::max(now, m_ownBusEndUs) + frameBusUs(frame);
    excuse(frame, true);
    return true;
}

qint64 CanLink::frameBusUs(const CanFrameData &frame) const
{
    const int bitrate = m_settings.bitrate > 0 ? m_settings.bitrate : 1000000;
    const double us = WireTime::canFrameUs(int(std::min<qsizetype>(frame.data.size(), 8)), frame.extended, bitrate,
                                           CanStuffing::WorstCase);
    return qint64(std::ceil(us));
}

// `frame` was (or will be) on the bus: the answers it outranks could not be sent meanwhile.
// Our own frames (`own`) count only when they outrank the answer strictly: our retries to a
// silent station (its own identifier) must not postpone each other's timeouts.
void CanLink::excuse(const CanFrameData &frame, bool own)
{
    const qint64 busUs = frameBusUs(frame);
    const quint64 key = priorityKey(frame.id, frame.extended);
    for (Pending &p : m_inFlight) {
        if (p.request.answerId < 0) {
            p.excusedUs += busUs;
            continue;
        }
        const quint64 answer = priorityKey(quint32(p.request.answerId), p.request.answerExtended);
        if (key < answer || (!own && key == answer))
            p.excusedUs += busUs;
    }
}

// When `p` times out unless more frames hold its answer back.
qint64 CanLink::dueUs(const Pending &p) const
{
    const int timeout = p.request.timeoutMs >= 0 ? p.request.timeoutMs : m_settings.responseTimeoutMs;
    const qint64 timeoutUs = qint64(timeout) * 1000;
    return std::min(p.sentUs + p.excusedUs + timeoutUs, p.sentUs + timeoutUs * StarvedTimeoutFactor);
}

CanLink::Lane &CanLink::laneFor(quint64 key)
{
    for (Lane &lane : m_lanes)
        if (lane.key == key)
            return lane;
    m_lanes.push_back(Lane{key, {}, 0});
    return m_lanes.back();
}

// The lane whose next request goes out next: of those with requests waiting, the one with
// the fewest in flight; between equals, round robin.
CanLink::Lane *CanLink::pickLane()
{
    // Forget lanes with nothing waiting and nothing in flight.
    for (size_t i = 0; i < m_lanes.size();) {
        if (m_lanes[i].queue.isEmpty() && m_lanes[i].inFlight == 0) {
            m_lanes.erase(m_lanes.begin() + qsizetype(i));
            if (m_nextLane > i)
                --m_nextLane;
        } else {
            ++i;
        }
    }
    const size_t n = m_lanes.size();
    Lane *best = nullptr;
    size_t bestIndex = 0;
    for (size_t k = 0; k < n; ++k) {
        const size_t i = (m_nextLane + k) % n;
        Lane &lane = m_lanes[i];
        if (lane.queue.isEmpty())
            continue;
        if (!best || lane.inFlight < best->inFlight) {
            best = &lane;
            bestIndex = i;
        }
    }
    if (best)
        m_nextLane = (bestIndex + 1) % n;
    return best;
}

void CanLink::release(const Pending &p)
{
    const quint64 key = laneKey(p.request.frame);
    for (Lane &lane : m_lanes)
        if (lane.key == key) {
            lane.inFlight = std::max(0, lane.inFlight - 1);
            return;
        }
}

void CanLink::pump()
{
    if (!isConnected())
        return;
    for (;;) {
        const bool windowFull = m_inFlight.size() >= m_settings.maxInFlight;
        if (!m_urgent.isEmpty()) {
            // An urgent frame that expects no reply does not wait for the window.
            if (windowFull && m_urgent.head().request.matcher)
                break;
            dispatch(m_urgent.dequeue());
            continue;
        }
        if (windowFull)
            break;
        Lane *lane = pickLane();
        if (!lane)
            break;
        dispatch(lane->queue.dequeue());
    }
    armTimer();
}

void CanLink::dispatch(Pending p)
{
    if (!p.reply)
        return;
    ++p.attempts;
    if (!writeNow(p.request.frame, p.request.note)) {
        p.reply->finishWithError(
            {ErrorCode::LinkClosed,
             tr("Cannot write to CAN interface %1: %2").arg(m_settings.toString(), m_device->errorString())});
        return;
    }
    if (!p.request.matcher) {
        p.reply->setAttempts(p.attempts);
        p.reply->finishEmpty();
        return;
    }
    p.sentUs = nowUs();
    // Our own frames queued ahead of it (and itself) must leave before the drive can answer.
    p.excusedUs = std::max<qint64>(0, m_ownBusEndUs - p.sentUs);
    ++laneFor(laneKey(p.request.frame)).inFlight;
    m_inFlight.append(p);
}

void CanLink::armTimer()
{
    if (m_inFlight.isEmpty()) {
        m_timer.stop();
        return;
    }
    qint64 earliest = dueUs(m_inFlight.first());
    for (const Pending &p : m_inFlight)
        earliest = std::min(earliest, dueUs(p));
    const qint64 waitMs = std::max<qint64>(0, (earliest - nowUs() + 999) / 1000);
    m_timer.start(static_cast<int>(waitMs));
}

void CanLink::onTick()
{
    const qint64 now = nowUs();
    for (int i = 0; i < m_inFlight.size();) {
        Pending &p = m_inFlight[i];
        if (!p.reply) {
            release(p);
            m_inFlight.removeAt(i);
            continue;
        }
        if (dueUs(p) > now) {
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
            Pending &q = m_inFlight[i]; // writeNow() touched the list's elements
            q.sentUs = nowUs();
            q.excusedUs = std::max<qint64>(0, m_ownBusEndUs - q.sentUs);
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
        release(p);
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
                release(p);
                m_inFlight.removeAt(i);
                break;
            }
        }
        excuse(frame);
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
