#pragma once

#include "core/drive/familybackend.h"

#include <QMap>
#include <QPointer>

namespace dd {

class CanLink;
class ServoCanDrive;
class ServoCanStationTracker;

// The `servo-can` family on one CAN bus: opens a CanLink from ConnectionSettings::can
// ("plugin:interface", e.g. "socketcan:can0", "virtualcan:can1"; bitrate 1 Mbit/s unless
// ConnectionSettings::bitrate says otherwise), owns the link's ServoCanStationTracker
// (heartbeats, alarms, keep-alive) and one ServoCanDrive per station asked for.
//
// Options (ConnectionSettings::options):
//   "servo-can.emergencyStop" = "disable" (default: 0x28, stop and torque off) | "hold"
//       (0x26, stop and keep holding the shaft, for vertical axes without a brake);
//   "servo-can.confirmReads" = false (default) | true (see ServoCanDrive);
//   "servo-can.maxInFlight" = N (pipelined reads, default the link's 32).
// stopAll() sends the emergency stop to every station whose heartbeat was seen and every
// station a Drive was made for.
class ServoCanBackend : public FamilyBackend
{
    Q_OBJECT
public:
    explicit ServoCanBackend(QObject *parent = nullptr);
    ~ServoCanBackend() override;

    Family family() const override;
    bool open(const ConnectionSettings &settings, TrafficTap *tap, Error *error) override;
    void close() override;
    bool isOpen() const override { return m_open; }
    // nullptr for an address outside 0..99.
    Drive *drive(int address) override;
    ServoCanDrive *servoDrive(int station);
    Discovery *createDiscovery(const ScanOptions &options) override;
    void stopAll() override;
    QString linkDescription() const override;

    CanLink *link() const { return m_link; }
    ServoCanStationTracker *tracker() const { return m_tracker; }
    bool emergencyStopHolds() const { return m_emergencyHolds; }

private:
    void configureDrive(ServoCanDrive *drive) const;
    void onLinkClosed(const Error &why);

    CanLink *m_link;
    ServoCanStationTracker *m_tracker;
    QMap<int, QPointer<ServoCanDrive>> m_drives;
    int m_bitrate = 0;
    bool m_open = false;
    bool m_emergencyHolds = false;
    bool m_confirmReads = false;
};

} // namespace dd
