#pragma once

#include "core/common/error.h"
#include "core/drive/discovery.h"
#include "core/drive/driveresult.h"
#include "core/link/connectionsettings.h"
#include "core/link/trafficrecord.h"

#include <QHash>
#include <QObject>
#include <QSet>
#include <functional>

class QThread;

namespace dd {

class Drive;
class DriveConnection;
class DriveReply;

// The GUI's way to the drives: owns an I/O thread on which every DriveConnection (link,
// family backend, drives) lives, so that a busy or blocked GUI never delays a keep-alive,
// a jog-lease check or a stop. Every method is called from the hub's own (GUI) thread and
// returns at once; callbacks run on that thread too. Connections are named by an id.
class DriveHub : public QObject
{
    Q_OBJECT
public:
    using Done = std::function<void(const DriveResult &)>;
    using Operation = std::function<DriveReply *(Drive &)>;
    using Progress = std::function<void(int done, int total)>;

    explicit DriveHub(QObject *parent = nullptr);
    ~DriveHub() override; // closes every connection and stops the thread

    // Opens a connection on the I/O thread; `done` gets the id (> 0) or an error.
    void openConnection(const ConnectionSettings &settings, std::function<void(int id, const Error &error)> done);
    // A drive still jogging on it (its button goes away with the tab) is stopped first; the
    // link then stays open for StopGraceMs so that the stop reaches the wire.
    void closeConnection(int id);
    static constexpr int StopGraceMs = 100;
    void closeAll();
    QList<int> connectionIds() const { return m_settings.keys(); }
    ConnectionSettings connectionSettings(int id) const { return m_settings.value(id); }

    // Runs `op` on the drive at `address` of connection `id`, on the I/O thread. `progress`
    // gets the reply's progress() (long reads and writes, backups) on this thread.
    void run(int id, int address, Operation op, Done done = {}, Progress progress = {});
    // Runs a scan; found/progress/finished arrive on this thread.
    void scan(int id, const ScanOptions &options, std::function<void(const DiscoveredDrive &)> found,
              std::function<void(int, int)> progress, std::function<void(const Error &)> finished);
    void cancelScan(int id);

    // STOP: every drive on every connection, emergency stop where the family has it.
    // Emits stopAllSent() at once (on this thread): whatever was moving was stopped.
    void stopAll();
    // Keep a jog alive (call at least every 100 ms while the jog button is held).
    void renewJogLease(int id, int address);

    // For tests: the I/O thread.
    QThread *ioThread() const { return m_thread; }

signals:
    void trafficRecorded(int id, const dd::TrafficRecord &record);
    void statusChanged(int id, int address, const dd::DriveStatus &status);
    void alarmChanged(int id, int address, int code);
    void jogLeaseExpired(int id, int address);
    void jogEnded(int id, int address, const dd::JogEnd &end);
    void linkLost(int id, const dd::Error &why);
    void stopAllSent(); // stopAll() was called: a motion watched since was interrupted

private:
    DriveConnection *connectionOnIo(int id) const;      // only on the I/O thread
    void watchDrive(int id, int address, Drive *drive); // on the I/O thread

    QThread *m_thread = nullptr;
    QObject *m_ioContext = nullptr;              // lives on the I/O thread
    QHash<int, DriveConnection *> m_connections; // objects live on the I/O thread
    QSet<DriveConnection *> m_closing;           // I/O thread: closed, stopping a jog
    QHash<int, ConnectionSettings> m_settings;   // GUI-side copy
    QHash<int, Discovery *> m_scans;             // I/O thread objects
    QHash<QPair<int, int>, bool> m_watched;      // I/O thread only
    int m_nextId = 1;
};

} // namespace dd
