#pragma once

#include "core/drive/discovery.h"

#include <QPointer>
#include <QSet>
#include <QTimer>

namespace dd {

class ServoCanStationTracker;

// Finds `servo-can` drives by listening: every drive in CAN mode (P74 = 1) sends a heartbeat
// every 30 ms, so listening ScanOptions::listenMs (300 ms by default: ten heartbeats) hears
// all of them. Each station is reported once, with its state ("idle", "running",
// "alarm 12") and the link's bitrate.
//
// Decision: no active probing (no 0x12 read to each station). A drive that sends no
// heartbeat is not in CAN communication mode and cannot be controlled over CAN anyway, and
// probing 100 stations costs 100 read timeouts. Every station heard is reported, whatever
// ScanOptions::from/to say (they are for address sweeps; a heartbeat costs nothing to take).
// Stations whose heartbeat the link's tracker already heard recently are reported at once.
class ServoCanDiscovery : public Discovery
{
    Q_OBJECT
public:
    ServoCanDiscovery(ServoCanStationTracker *tracker, const ScanOptions &options, int bitrate,
                      QObject *parent = nullptr);

    void start() override;
    void cancel() override;
    bool isRunning() const { return m_running; }

private:
    void onHeartbeat(int station, quint8 state, qint32 position);
    void onTick();
    void finishScan(const Error &error);
    void reportStation(int station);

    QPointer<ServoCanStationTracker> m_tracker;
    ScanOptions m_options;
    int m_bitrate;
    QSet<int> m_reported;
    QTimer m_tick; // progress
    QTimer m_end;  // listenMs
    qint64 m_startMs = 0;
    bool m_running = false;
};

} // namespace dd
