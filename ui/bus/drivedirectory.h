#pragma once

#include "core/common/error.h"
#include "core/drive/drivetypes.h"
#include "core/link/connectionsettings.h"
#include "ui/bus/driveinfo.h"

#include <QMap>
#include <QObject>

namespace dd {

class DriveHub;

// The GUI's picture of the bus: the open connections and the drives found on each, with
// the last known identity and status. It listens to the hub (status, alarms, lost links)
// and fetches a drive's identity once when it is added. The bus tree, the drive tabs, the
// status poller and the status bar read it; the ConnectionController fills it.
class DriveDirectory : public QObject
{
    Q_OBJECT
public:
    enum class LinkState { Open, Lost };

    explicit DriveDirectory(DriveHub *hub, QObject *parent = nullptr);

    DriveHub *hub() const { return m_hub; }

    void addConnection(int id, const ConnectionSettings &settings);
    void removeConnection(int id);
    void clear();
    QList<int> connections() const { return m_connections.keys(); }
    bool hasConnection(int id) const { return m_connections.contains(id); }
    ConnectionSettings connectionSettings(int id) const;
    LinkState linkState(int id) const;
    QString linkError(int id) const;

    // Adds a drive found by a scan (again: updates what the scan said).
    void addDrive(int id, const DiscoveredDrive &drive);
    QList<int> drives(int id) const; // addresses, ascending
    bool hasDrive(int id, int address) const;
    DiscoveredDrive discovered(int id, int address) const;
    DriveInfo info(int id, int address) const;
    // A status read result (the hub's statusChanged arrives here too).
    void updateStatus(int id, int address, const DriveStatus &status);
    // A status read failed: shows the drive as not answering until the next status.
    void markNoAnswer(int id, int address);
    // Reads the drive's identity again (driveChanged follows).
    void refresh(int id, int address);

signals:
    void connectionAdded(int id);
    void connectionRemoved(int id);
    void linkStateChanged(int id);
    void driveAdded(int id, int address);
    // Identity, capabilities or status changed.
    void driveChanged(int id, int address);
    void statusChanged(int id, int address, const dd::DriveStatus &status);
    void alarmChanged(int id, int address, int code);
    void errorOccurred(const dd::Error &error);

protected:
    // A language switch: the drives' descriptions (reasons, channel names) are made again.
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    struct Entry
    {
        DiscoveredDrive discovered;
        DriveInfo info;
    };
    struct Connection
    {
        ConnectionSettings settings;
        LinkState state = LinkState::Open;
        QString error;
        QMap<int, Entry> drives;
    };

    void onAlarm(int id, int address, int code);
    void onLinkLost(int id, const Error &why);

    DriveHub *m_hub = nullptr;
    QMap<int, Connection> m_connections;
};

} // namespace dd
