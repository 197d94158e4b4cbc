#pragma once

#include "core/protocol/servocan/servocan.h"

#include <QElapsedTimer>
#include <QList>
#include <QMap>
#include <QObject>
#include <QTimer>

#include <array>

namespace dd {

class CanLink;

// The link-wide half of the `servo-can` protocol (docs/protocols/servo-can.md): watches every
// frame on one CanLink for heartbeats (0x10) and alarm frames (0x05), keeps per-station
// state, and sends the keep-alive (0x08) every 100 ms to every station this program holds a
// motion lease on.
//
// Motion lease (docs/reliability.md, "The keep-alive belongs to whoever commands motion"):
// the keep-alive is what keeps a drive's motion going — without it the drive's 2 s watchdog
// stops the axis. So only the program that commands the motion sends it: holdMotion() is
// called by the drive just before it sends a motion command (0x20 jog, 0x21 / 0x22 move) and
// sends one keep-alive at once; the lease ends with releaseMotion() (a stop or a disable
// went out), when the station's heartbeat shows it at rest after the motion (or shows no
// motion 1 s after the last motion command), when the station goes offline (DriveDesk cannot
// see what it does) and when the link closes. A program that only reads (monitor, trend,
// capture, backup) holds no lease and sends no keep-alive, so a motion commanded by a
// program that died is stopped by the drive's watchdog. One tracker per link: drives and
// discovery share it.
//
// Timing: the keep-alive runs on a periodic Qt::PreciseTimer while a lease is held; every
// tick sends one frame to each leased station. The gap between ticks is measured (stats())
// so tests and the benchmark can prove the drive's 2 s watchdog is never near during a
// motion. A station is offline when no heartbeat came for offlineMs() (200 ms by default:
// more than six missed 30 ms heartbeats); the check runs every 50 ms.
class ServoCanStationTracker : public QObject
{
    Q_OBJECT
public:
    struct Station
    {
        bool seen = false;   // a heartbeat arrived since the link was opened
        bool online = false; // and the last one is younger than offlineMs()
        quint8 state = servocan::kHeartbeatIdle;
        qint32 position = 0;
        int alarmCode = -1;          // from 0x05 frames (0 = none); -1 while none was reported
        qint64 lastHeartbeatMs = -1; // tracker clock (elapsedMs())
        quint64 heartbeats = 0;

        bool running() const { return !servocan::isHeartbeatIdle(state); }
    };

    struct Stats
    {
        quint64 keepAliveTicks = 0; // ticks that sent at least one frame
        quint64 keepAliveFrames = 0;
        double maxKeepAliveGapMs = 0; // longest gap between two consecutive ticks
        double lastKeepAliveGapMs = 0;
        quint64 heartbeats = 0;
        quint64 alarmFrames = 0;
        quint64 undecodable = 0; // frames with a servo-can ID that did not decode
    };

    explicit ServoCanStationTracker(CanLink *link, QObject *parent = nullptr);
    ~ServoCanStationTracker() override;

    CanLink *link() const { return m_link; }

    const Station &station(int station) const;
    bool isOnline(int station) const;
    QList<int> seenStations() const; // stations whose heartbeat was seen, ascending
    QList<int> onlineStations() const;

    int offlineMs() const { return m_offlineMs; }
    void setOfflineMs(int ms) { m_offlineMs = ms; }
    int keepAlivePeriodMs() const { return m_keepAlive.interval(); }
    // For tests and field diagnosis only: a period above 2000 ms lets the drives' watchdog trip.
    void setKeepAlivePeriodMs(int ms) { m_keepAlive.setInterval(ms); }
    // Stops / resumes the keep-alive without closing the link (tests of the drive watchdog).
    void setKeepAliveSuspended(bool suspended);
    bool isKeepAliveSuspended() const { return m_suspended; }

    // Motion leases (see above).
    void holdMotion(int station);
    void releaseMotion(int station);
    bool holdsMotion(int station) const { return m_leases.contains(station); }
    QList<int> motionStations() const { return m_leases.keys(); } // ascending
    // A lease whose motion never showed in a heartbeat ends this long after its last command.
    static constexpr int kLeaseStartMs = 1000;

    const Stats &stats() const { return m_stats; }
    void resetStats();
    qint64 elapsedMs() const { return m_clock.elapsed(); }

    // Forget every station and stop the keep-alive (the link was closed).
    void reset();

signals:
    void heartbeat(int station, quint8 state, qint32 position);
    void alarmReported(int station, int code);
    void stationOnline(int station);
    void stationOffline(int station);
    void motionLeaseChanged(int station, bool held);
    // Any decoded servo-can frame (replies, echoes, ...), for listeners that want more.
    void messageReceived(const dd::servocan::Message &message);

private:
    void onFrame(const CanFrameData &frame);
    void onKeepAliveTick();
    void onOfflineCheck();
    void startKeepAlive();
    void endLease(int station, const char *why);

    struct Lease
    {
        qint64 lastCommandMs = 0; // tracker clock
        bool sawRunning = false;  // a heartbeat showed the motion since the last command
    };

    CanLink *m_link;
    std::array<Station, servocan::kStationCount> m_stations{};
    QList<int> m_seen; // ascending
    QMap<int, Lease> m_leases;
    QTimer m_keepAlive;
    QTimer m_offlineCheck;
    QElapsedTimer m_clock;
    qint64 m_lastTickNs = -1;
    int m_offlineMs = 200;
    bool m_suspended = false;
    Stats m_stats;
};

} // namespace dd
