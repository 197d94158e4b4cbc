#include "ui/bus/connectioncontroller.h"

#include "core/drive/drivehub.h"
#include "ui/bus/drivedirectory.h"
#include "ui/bus/statuspoller.h"
#include "ui/common/displaytext.h"

#include <QPointer>

namespace dd {

ConnectionController::ConnectionController(DriveDirectory *directory, StatusPoller *poller, QObject *parent)
    : QObject(parent)
    , m_directory(directory)
    , m_hub(directory->hub())
    , m_poller(poller)
{
}

void ConnectionController::connectTo(const ConnectRequest &request)
{
    Job job;
    job.request = request;
    if (request.detect)
        job.request.scan = true; // detection is a scan
    job.attempts = request.attempts();
    m_queue.append(job);
    if (!m_busy)
        startNext();
}

void ConnectionController::rescan(int id)
{
    if (!m_directory->hasConnection(id))
        return;
    Job job;
    job.request = m_requests.value(id);
    job.request.settings = m_directory->connectionSettings(id);
    job.request.detect = false;
    job.request.scan = true;
    job.attempts = {job.request.settings};
    job.rescanId = id;
    m_queue.append(job);
    if (!m_busy)
        startNext();
}

void ConnectionController::disconnectLink(int id)
{
    for (auto it = m_queue.begin(); it != m_queue.end();)
        it = it->rescanId == id ? m_queue.erase(it) : it + 1;
    m_hub->closeConnection(id);
    m_directory->removeConnection(id);
    m_requests.remove(id);
    m_poller->pauseConnection(id, false);
    if (m_busy && m_currentId == id) {
        // Closing the link deletes its scan: no finished() will come for it.
        m_currentId = 0;
        m_cancelled = true;
        finishJob();
    }
}

void ConnectionController::disconnectAll()
{
    m_queue.clear();
    const QList<int> ids = m_directory->connections();
    for (int id : ids)
        disconnectLink(id);
    if (m_busy)
        cancel();
}

void ConnectionController::cancel()
{
    m_queue.clear();
    if (!m_busy)
        return;
    m_cancelled = true;
    if (m_currentId > 0)
        m_hub->cancelScan(m_currentId); // onScanFinished follows
    // An open in progress finishes in onOpened, which sees m_cancelled.
}

void ConnectionController::setBusy(bool busy)
{
    if (m_busy == busy)
        return;
    m_busy = busy;
    emit busyChanged(busy);
}

void ConnectionController::startNext()
{
    if (m_queue.isEmpty()) {
        const bool ok = m_foundTotal > 0 || (m_linksOpened > 0 && m_errors.isEmpty());
        const QString text = summary();
        setBusy(false);
        m_foundTotal = 0;
        m_linksOpened = 0;
        m_errors.clear();
        emit finished(text, ok);
        return;
    }
    if (!m_busy) {
        m_foundTotal = 0;
        m_linksOpened = 0;
        m_errors.clear();
        emit foundCountChanged(0);
        setBusy(true);
    }
    m_job = m_queue.takeFirst();
    m_cancelled = false;
    m_currentId = 0;
    if (m_job.rescanId > 0)
        startScan(m_job.rescanId);
    else
        runAttempt();
}

QString ConnectionController::stageText(const ConnectionSettings &s, bool scanning) const
{
    QString text = scanning ? tr("Scanning %1 for %2 drives, addresses %3–%4…")
                                  .arg(s.linkName(), DisplayText::familyName(s.family))
                                  .arg(m_job.request.scanOptionsFor(s).from)
                                  .arg(m_job.request.scanOptionsFor(s).to)
                            : tr("Opening %1 (%2)…").arg(s.linkName(), familyId(s.family));
    if (m_job.attempts.size() > 1)
        text += QLatin1Char(' ') + tr("(try %1 of %2)").arg(m_job.attempt + 1).arg(m_job.attempts.size());
    return text;
}

void ConnectionController::runAttempt()
{
    const ConnectionSettings s = m_job.attempts.at(m_job.attempt);
    emit stageChanged(stageText(s, false));
    QPointer<ConnectionController> self(this);
    m_hub->openConnection(s, [self](int id, const Error &error) {
        if (self)
            self->onOpened(id, error);
    });
}

void ConnectionController::addConnectionOnce(int id, const ConnectionSettings &s)
{
    if (m_directory->hasConnection(id))
        return;
    m_directory->addConnection(id, s);
    ++m_linksOpened;
    emit connected(id);
}

void ConnectionController::onOpened(int id, const Error &error)
{
    if (error.isError()) {
        attemptFailed(error);
        return;
    }
    if (m_cancelled) {
        m_hub->closeConnection(id);
        finishJob();
        return;
    }
    const ConnectionSettings s = m_job.attempts.at(m_job.attempt);
    ConnectRequest r = m_job.request;
    r.settings = s;
    r.detect = false;
    m_requests.insert(id, r);
    m_currentId = id;
    if (!m_job.request.detect)
        addConnectionOnce(id, s);
    if (m_job.request.scan)
        startScan(id);
    else
        finishJob();
}

void ConnectionController::startScan(int id)
{
    m_currentId = id;
    m_foundInAttempt = 0;
    m_poller->pauseConnection(id, true);
    const ConnectionSettings s = m_directory->hasConnection(id) ? m_directory->connectionSettings(id)
                                                                : m_job.attempts.at(m_job.attempt);
    emit stageChanged(stageText(s, true));
    QPointer<ConnectionController> self(this);
    m_hub->scan(
        id, m_job.request.scanOptionsFor(s),
        [self, id, s](const DiscoveredDrive &d) {
            if (!self)
                return;
            self->addConnectionOnce(id, s);
            if (!self->m_directory->hasConnection(id))
                return;
            const bool isNew = !self->m_directory->hasDrive(id, d.address);
            self->m_directory->addDrive(id, d);
            if (isNew) {
                ++self->m_foundInAttempt;
                ++self->m_foundTotal;
                emit self->foundCountChanged(self->m_foundTotal);
            }
        },
        [self, id](int done, int total) {
            if (self && self->m_currentId == id)
                emit self->progress(done, total);
        },
        [self, id](const Error &e) {
            if (self)
                self->onScanFinished(id, e);
        });
}

void ConnectionController::onScanFinished(int id, const Error &error)
{
    m_poller->pauseConnection(id, false);
    if (id != m_currentId)
        return; // disconnected meanwhile
    if (error.isError() && error.code != ErrorCode::Cancelled) {
        m_errors.append(error);
        emit errorOccurred(error);
    }
    const bool keep = !m_job.request.detect || m_foundInAttempt > 0 || m_job.rescanId > 0;
    if (keep) {
        finishJob();
        return;
    }
    // Detection: nothing of this family here; close and try the next.
    m_hub->closeConnection(id);
    m_requests.remove(id);
    m_currentId = 0;
    if (m_cancelled || m_job.attempt + 1 >= m_job.attempts.size()) {
        finishJob();
        return;
    }
    ++m_job.attempt;
    runAttempt();
}

void ConnectionController::attemptFailed(const Error &error)
{
    // A port that cannot be opened will not open for another family either.
    const bool tryNext = m_job.request.detect && !m_cancelled && error.code == ErrorCode::NotSupported
        && m_job.attempt + 1 < m_job.attempts.size();
    if (tryNext) {
        ++m_job.attempt;
        runAttempt();
        return;
    }
    m_errors.append(error);
    emit errorOccurred(error);
    if (error.code == ErrorCode::OpenFailed && m_job.attempt < m_job.attempts.size()) {
        const ConnectionSettings &s = m_job.attempts.at(m_job.attempt);
        if (!s.isCan()) {
            if (const auto denied = serialAccessProblem(s.port))
                emit serialAccessDenied(*denied);
        }
    }
    finishJob();
}

void ConnectionController::finishJob()
{
    m_currentId = 0;
    startNext();
}

QString ConnectionController::summary() const
{
    if (m_foundTotal > 0)
        return tr("Found %n drive(s).", nullptr, m_foundTotal);
    if (!m_errors.isEmpty())
        return m_errors.last().message;
    if (m_cancelled)
        return tr("Scan cancelled.");
    if (m_linksOpened > 0 && !m_job.request.scan)
        return tr("Connected.");
    return tr("No drive answered. Check the wiring and termination, the baud rate or bitrate, "
              "the family and the address range.");
}

} // namespace dd
