#pragma once

#include "core/common/error.h"
#include "core/drive/drivetypes.h"
#include "core/link/serialaccess.h"
#include "ui/bus/connectrequest.h"

#include <QHash>
#include <QList>
#include <QObject>

namespace dd {

class DriveDirectory;
class DriveHub;
class StatusPoller;

// Runs "connect, then scan" through the DriveHub: opens the link, scans the address range
// (pausing the status poller on that link meanwhile) and puts the connection and the drives
// it finds into the DriveDirectory. With "detect" it tries the families of
// ConnectRequest::attempts() in turn and keeps the first connection that finds a drive
// (the others are closed again). Requests made while one runs are queued (the demo bench
// connects three links in a row). Everything is asynchronous; progress is reported by
// signals for the ScanProgressWidget.
class ConnectionController : public QObject
{
    Q_OBJECT
public:
    ConnectionController(DriveDirectory *directory, StatusPoller *poller, QObject *parent = nullptr);

    void connectTo(const ConnectRequest &request);
    // Scans an open connection again with the options it was opened with.
    void rescan(int id);
    void disconnectLink(int id);
    void disconnectAll();
    // Cancels the running scan / detection and everything queued.
    void cancel();
    bool isBusy() const { return m_busy; }

signals:
    void busyChanged(bool busy);
    void stageChanged(const QString &text);
    void progress(int done, int total);
    void foundCountChanged(int count);
    // The job and the queue are done: how many drives were found, or why nothing was.
    void finished(const QString &summary, bool ok);
    void connected(int id);
    void errorOccurred(const dd::Error &error);
    // A serial port could not be opened because this user may not use it (after errorOccurred).
    void serialAccessDenied(const dd::SerialAccessProblem &problem);

private:
    struct Job
    {
        ConnectRequest request;
        QList<ConnectionSettings> attempts;
        int attempt = 0;
        int rescanId = 0; // > 0: scan this open connection only
    };

    void startNext();
    void runAttempt();
    void onOpened(int id, const Error &error);
    void startScan(int id);
    void onScanFinished(int id, const Error &error);
    void attemptFailed(const Error &error);
    void finishJob();
    void setBusy(bool busy);
    QString summary() const;
    QString stageText(const ConnectionSettings &s, bool scanning) const;
    void addConnectionOnce(int id, const ConnectionSettings &s);

    DriveDirectory *m_directory = nullptr;
    DriveHub *m_hub = nullptr;
    StatusPoller *m_poller = nullptr;
    QList<Job> m_queue;
    Job m_job;
    bool m_busy = false;
    bool m_cancelled = false;
    int m_currentId = 0;
    int m_foundInAttempt = 0;
    int m_foundTotal = 0;
    int m_linksOpened = 0;
    QList<Error> m_errors;
    QHash<int, ConnectRequest> m_requests; // by connection id, for rescans
};

} // namespace dd
