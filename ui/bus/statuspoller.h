#pragma once

#include "core/common/error.h"

#include <QObject>
#include <QSet>
#include <QTimer>

namespace dd {

class DriveDirectory;

// Reads the status of every known drive at a steady pace so that the bus tree shows live
// state for families that send no heartbeat. One request per drive at a time (a slow link
// is never flooded); a connection being scanned is skipped (the scan owns the link then).
// Results arrive through DriveHub::statusChanged → DriveDirectory.
class StatusPoller : public QObject
{
    Q_OBJECT
public:
    static constexpr int DefaultIntervalMs = 500;

    explicit StatusPoller(DriveDirectory *directory, QObject *parent = nullptr);

    void setIntervalMs(int ms) { m_timer.setInterval(ms); }
    int intervalMs() const { return m_timer.interval(); }
    void setEnabled(bool on);
    bool isEnabled() const { return m_timer.isActive(); }
    // While a connection is paused (scanning) none of its drives is polled.
    void pauseConnection(int id, bool paused);

signals:
    // A status read failed (the drive did not answer, the link is gone ...).
    void pollFailed(int id, int address, const dd::Error &error);

private:
    void poll();

    DriveDirectory *m_directory = nullptr;
    QTimer m_timer;
    QSet<quint64> m_inFlight; // (id << 32) | address
    QSet<int> m_paused;
};

} // namespace dd
