#pragma once

#include "core/report/driverecord.h"

#include <QList>
#include <QObject>
#include <QPair>
#include <QStringList>

namespace dd {

class DriveDirectory;
class RecordSession;

// Reads what a commissioning record says about the drives chosen in the GUI, through the
// hub: every readable parameter and the active alarm; adds the identity the directory knows,
// the session's alarms and link health, and the verification journal's last restore or
// write. finished() once, with one DriveRecord per drive that answered and a translated
// line per drive that did not.
class RecordGatherer : public QObject
{
    Q_OBJECT
public:
    RecordGatherer(DriveDirectory *directory, RecordSession *session, QObject *parent = nullptr);

    // (connection id, address) pairs.
    void gather(const QList<QPair<int, int>> &drives);
    bool isBusy() const { return m_busy; }

signals:
    void progress(int done, int total);
    void finished(const QList<dd::DriveRecord> &records, const QStringList &problems);

private:
    void next();
    void readAlarm(const QPair<int, int> &drive, DriveRecord record);
    void done(const QPair<int, int> &drive, const DriveRecord &record);

    DriveDirectory *m_directory;
    RecordSession *m_session;
    QList<QPair<int, int>> m_pending;
    QList<DriveRecord> m_records;
    QStringList m_problems;
    int m_total = 0;
    bool m_busy = false;
};

} // namespace dd
