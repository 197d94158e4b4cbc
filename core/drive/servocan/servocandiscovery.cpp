#include "core/drive/servocan/servocandiscovery.h"

#include "core/drive/servocan/servocanstationtracker.h"
#include "core/link/canlink.h"
#include "core/protocol/servocan/servocan.h"

#include <QCoreApplication>

namespace dd {

namespace sc = servocan;

ServoCanDiscovery::ServoCanDiscovery(ServoCanStationTracker *tracker, const ScanOptions &options, int bitrate,
                                     QObject *parent)
    : Discovery(parent)
    , m_tracker(tracker)
    , m_options(options)
    , m_bitrate(bitrate)
    , m_tick(this)
    , m_end(this)
{
    qRegisterMetaType<dd::DiscoveredDrive>();
    m_tick.setInterval(50);
    connect(&m_tick, &QTimer::timeout, this, &ServoCanDiscovery::onTick);
    m_end.setSingleShot(true);
    m_end.setTimerType(Qt::PreciseTimer);
    connect(&m_end, &QTimer::timeout, this, [this] {
        if (!m_running)
            return;
        emit progress(std::max(1, m_options.listenMs), std::max(1, m_options.listenMs));
        finishScan(Error::none());
    });
}

void ServoCanDiscovery::start()
{
    if (m_running)
        return;
    if (!m_tracker || !m_tracker->link()) {
        m_running = true;
        QMetaObject::invokeMethod(
            this,
            [this] {
                finishScan({ErrorCode::LinkClosed, tr("The CAN link is not open.")});
            },
            Qt::QueuedConnection);
        return;
    }
    m_running = true;
    m_startMs = m_tracker->elapsedMs();
    connect(m_tracker, &ServoCanStationTracker::heartbeat, this, &ServoCanDiscovery::onHeartbeat);
    connect(m_tracker->link(), &CanLink::closed, this, [this](const Error &why) {
        finishScan(why.isError() ? why : Error{ErrorCode::LinkClosed, tr("The CAN link was closed.")});
    });
    // Stations already heard recently: report them from the event loop (never inside start()).
    QMetaObject::invokeMethod(
        this,
        [this] {
            if (!m_running || !m_tracker)
                return;
            for (int s : m_tracker->onlineStations())
                reportStation(s);
        },
        Qt::QueuedConnection);
    m_tick.start();
    m_end.start(std::max(0, m_options.listenMs));
}

void ServoCanDiscovery::cancel()
{
    if (m_running)
        finishScan({ErrorCode::Cancelled, tr("The scan was cancelled.")});
}

void ServoCanDiscovery::onHeartbeat(int station, quint8, qint32)
{
    if (m_running)
        reportStation(station);
}

void ServoCanDiscovery::reportStation(int station)
{
    if (m_reported.contains(station) || !m_tracker)
        return;
    m_reported.insert(station);
    const ServoCanStationTracker::Station &st = m_tracker->station(station);
    DiscoveredDrive d;
    d.family = Family::ServoCan;
    d.address = station;
    d.bitrate = m_bitrate;
    d.link = m_tracker->link()->name();
    if (st.alarmCode > 0)
        d.state = tr("alarm %1").arg(st.alarmCode);
    else
        d.state = st.running() ? tr("running") : tr("idle");
    report(d);
}

void ServoCanDiscovery::onTick()
{
    if (!m_running || !m_tracker)
        return;
    const qint64 elapsed = m_tracker->elapsedMs() - m_startMs;
    const int total = std::max(1, m_options.listenMs);
    emit progress(static_cast<int>(std::min<qint64>(elapsed, total)), total);
}

void ServoCanDiscovery::finishScan(const Error &error)
{
    if (!m_running)
        return;
    m_running = false;
    m_tick.stop();
    m_end.stop();
    if (m_tracker) {
        disconnect(m_tracker, nullptr, this, nullptr);
        if (m_tracker->link())
            disconnect(m_tracker->link(), nullptr, this, nullptr);
    }
    emit finished(error);
}

} // namespace dd
