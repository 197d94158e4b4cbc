#include "core/drive/servocan/servocanstationtracker.h"

#include "core/link/canlink.h"

#include <QLoggingCategory>

#include <algorithm>

Q_LOGGING_CATEGORY(lcServoCanTracker, "drivedesk.drive.servocan", QtInfoMsg)

namespace dd {

namespace sc = servocan;

ServoCanStationTracker::ServoCanStationTracker(CanLink *link, QObject *parent)
    : QObject(parent)
    , m_link(link)
    , m_keepAlive(this)
    , m_offlineCheck(this)
{
    qRegisterMetaType<dd::servocan::Message>();
    m_clock.start();
    m_keepAlive.setTimerType(Qt::PreciseTimer);
    m_keepAlive.setInterval(static_cast<int>(sc::kKeepAlivePeriod.count()));
    connect(&m_keepAlive, &QTimer::timeout, this, &ServoCanStationTracker::onKeepAliveTick);
    m_offlineCheck.setInterval(50);
    connect(&m_offlineCheck, &QTimer::timeout, this, &ServoCanStationTracker::onOfflineCheck);
    connect(link, &CanLink::frameReceived, this, &ServoCanStationTracker::onFrame);
    connect(link, &CanLink::closed, this, &ServoCanStationTracker::reset);
}

ServoCanStationTracker::~ServoCanStationTracker() = default;

const ServoCanStationTracker::Station &ServoCanStationTracker::station(int station) const
{
    static const Station none;
    return sc::isValidStation(station) ? m_stations[static_cast<size_t>(station)] : none;
}

bool ServoCanStationTracker::isOnline(int s) const
{
    return station(s).online;
}

QList<int> ServoCanStationTracker::seenStations() const
{
    return m_seen;
}

QList<int> ServoCanStationTracker::onlineStations() const
{
    QList<int> out;
    for (int s : m_seen)
        if (m_stations[static_cast<size_t>(s)].online)
            out.append(s);
    return out;
}

void ServoCanStationTracker::setKeepAliveSuspended(bool suspended)
{
    m_suspended = suspended;
    if (suspended) {
        m_keepAlive.stop();
    } else if (!m_leases.isEmpty() && !m_keepAlive.isActive()) {
        startKeepAlive();
    }
}

void ServoCanStationTracker::holdMotion(int station)
{
    if (!sc::isValidStation(station))
        return;
    const bool isNew = !m_leases.contains(station);
    Lease &lease = m_leases[station];
    lease.lastCommandMs = m_clock.elapsed();
    lease.sawRunning = false;
    if (isNew) {
        qCDebug(lcServoCanTracker) << "station" << station << "motion lease: keep-alive starts";
        emit motionLeaseChanged(station, true);
    }
    if (!m_offlineCheck.isActive())
        m_offlineCheck.start();
    if (m_suspended)
        return;
    // One at once, ahead of the motion command: a drive that took itself offline is back
    // before the command arrives, and its 2 s count starts now.
    if (m_link->send(sc::keepAlive(static_cast<quint8>(station)), QStringLiteral("keep-alive (motion lease)")))
        ++m_stats.keepAliveFrames;
    if (!m_keepAlive.isActive())
        startKeepAlive();
}

void ServoCanStationTracker::releaseMotion(int station)
{
    endLease(station, "released");
}

void ServoCanStationTracker::endLease(int station, const char *why)
{
    if (!m_leases.remove(station))
        return;
    qCDebug(lcServoCanTracker) << "station" << station << "motion lease ended (" << why << "): keep-alive stops";
    if (m_leases.isEmpty())
        m_keepAlive.stop();
    emit motionLeaseChanged(station, false);
}

void ServoCanStationTracker::resetStats()
{
    m_stats = {};
    m_lastTickNs = -1;
}

void ServoCanStationTracker::reset()
{
    m_keepAlive.stop();
    m_offlineCheck.stop();
    m_lastTickNs = -1;
    const QList<int> leased = m_leases.keys();
    m_leases.clear();
    for (int s : leased)
        emit motionLeaseChanged(s, false);
    const QList<int> seen = m_seen;
    m_seen.clear();
    for (int s : seen) {
        const bool wasOnline = m_stations[static_cast<size_t>(s)].online;
        m_stations[static_cast<size_t>(s)] = Station{};
        if (wasOnline)
            emit stationOffline(s);
    }
}

void ServoCanStationTracker::onFrame(const CanFrameData &frame)
{
    if (frame.extended || frame.id < sc::kIdBase || frame.id > sc::kMaxId)
        return; // not ours: other IDs belong to the drive's internals or to other devices
    const Decoded<sc::Message> d = sc::decode(frame);
    if (!d.ok()) {
        ++m_stats.undecodable;
        qCDebug(lcServoCanTracker) << "undecodable frame" << Qt::hex << frame.id << frame.data.toHex(' ') << d.error;
        return;
    }
    const sc::Message &m = *d.value;
    Station &st = m_stations[m.station];
    if (m.command == sc::Command::Heartbeat) {
        ++m_stats.heartbeats;
        ++st.heartbeats;
        st.state = m.b2;
        st.position = m.value;
        st.lastHeartbeatMs = m_clock.elapsed();
        const bool wasOnline = st.online;
        st.online = true;
        if (!st.seen) {
            st.seen = true;
            m_seen.insert(std::lower_bound(m_seen.begin(), m_seen.end(), int(m.station)), m.station);
            qCDebug(lcServoCanTracker) << "station" << m.station << "first heartbeat";
            if (!m_offlineCheck.isActive())
                m_offlineCheck.start();
        }
        if (!wasOnline)
            emit stationOnline(m.station);
        const auto lease = m_leases.find(m.station);
        if (lease != m_leases.end()) {
            if (st.running())
                lease->sawRunning = true;
            else if (lease->sawRunning || st.lastHeartbeatMs - lease->lastCommandMs > kLeaseStartMs)
                endLease(m.station, "at rest");
        }
        emit heartbeat(m.station, m.b2, m.value);
    } else if (m.command == sc::Command::Alarm) {
        ++m_stats.alarmFrames;
        st.alarmCode = m.alarmCode();
        emit alarmReported(m.station, m.alarmCode());
    }
    emit messageReceived(m);
}

void ServoCanStationTracker::startKeepAlive()
{
    m_lastTickNs = -1;
    m_keepAlive.start();
}

void ServoCanStationTracker::onKeepAliveTick()
{
    if (m_leases.isEmpty() || m_suspended)
        return;
    const qint64 now = m_clock.nsecsElapsed();
    if (m_lastTickNs >= 0) {
        const double gap = double(now - m_lastTickNs) / 1e6;
        m_stats.lastKeepAliveGapMs = gap;
        m_stats.maxKeepAliveGapMs = std::max(m_stats.maxKeepAliveGapMs, gap);
    }
    m_lastTickNs = now;
    ++m_stats.keepAliveTicks;
    const QList<int> leased = m_leases.keys();
    for (int s : leased) {
        if (m_link->send(sc::keepAlive(static_cast<quint8>(s)), QStringLiteral("keep-alive")))
            ++m_stats.keepAliveFrames;
    }
}

void ServoCanStationTracker::onOfflineCheck()
{
    const qint64 now = m_clock.elapsed();
    // A lease on a station that shows no heartbeat (never heard, or gone) ends once its
    // motion had time to show: nothing here can see what that drive does.
    const QList<int> leased = m_leases.keys();
    for (int s : leased)
        if (!m_stations[static_cast<size_t>(s)].online && now - m_leases.value(s).lastCommandMs > kLeaseStartMs)
            endLease(s, "no heartbeat");
    for (int s : std::as_const(m_seen)) {
        Station &st = m_stations[static_cast<size_t>(s)];
        if (st.online && now - st.lastHeartbeatMs > m_offlineMs) {
            st.online = false;
            qCDebug(lcServoCanTracker) << "station" << s << "offline: no heartbeat for" << now - st.lastHeartbeatMs
                                       << "ms";
            endLease(s, "offline"); // DriveDesk cannot see what it does: its watchdog stops it
            emit stationOffline(s);
        }
    }
}

} // namespace dd
