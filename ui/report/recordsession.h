#pragma once

#include "core/report/recordalarm.h"
#include "core/report/recordlinkhealth.h"

#include <QHash>
#include <QList>
#include <QObject>

namespace dd {

class DriveDirectory;
class DriveHub;
class LinkHealthCounter;
struct TrafficRecord;

// What the GUI notes during a session for a commissioning record: the alarms every drive
// raised and cleared (from the directory's alarm changes) and each drive's link health
// (core/link's LinkHealth per address: requests, turnaround, timeouts, checksum errors, late
// replies, retries; and failed operations) since its connection was opened. Lives as long
// as the main window.
class RecordSession : public QObject
{
    Q_OBJECT
public:
    RecordSession(DriveHub *hub, DriveDirectory *directory, QObject *parent = nullptr);

    QList<RecordAlarm> alarms(int connectionId, int address) const;
    RecordLinkHealth linkHealth(int connectionId, int address) const;
    // An operation on the drive failed (counted in its link health).
    void countError(int connectionId, int address);

private:
    void onAlarm(int connectionId, int address, int code);
    void onTraffic(int connectionId, const TrafficRecord &record);
    LinkHealthCounter *counter(int connectionId);

    DriveDirectory *m_directory;
    QHash<QPair<int, int>, QList<RecordAlarm>> m_alarms;
    QHash<int, LinkHealthCounter *> m_links;
};

} // namespace dd
