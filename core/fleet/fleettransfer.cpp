#include "core/fleet/fleettransfer.h"

#include "core/drive/drive.h"
#include "core/drive/parametertransfer.h"

#include <QTimer>

namespace dd {

FleetTransfer::FleetTransfer(const QList<Drive *> &drives, QObject *parent)
    : QObject(parent)
{
    for (Drive *d : drives)
        m_drives.append(d);
}

FleetTransfer::~FleetTransfer() = default;

void FleetTransfer::backup()
{
    begin(Job::Backup);
}

void FleetTransfer::restore(const BackupFile &file, const RestoreOptions &options)
{
    m_file = file;
    m_files.clear();
    m_options = options;
    begin(Job::Restore);
}

void FleetTransfer::restoreEach(const QVector<BackupFile> &files, const RestoreOptions &options)
{
    Q_ASSERT(files.size() == m_drives.size());
    m_files = files;
    m_options = options;
    begin(Job::Restore);
}

void FleetTransfer::begin(Job job)
{
    if (m_running)
        return;
    m_job = job;
    m_running = true;
    m_stopping = false;
    m_next = 0;
    qDeleteAll(m_transfers);
    m_transfers.clear();
    m_results.clear();
    for (const QPointer<Drive> &d : std::as_const(m_drives)) {
        FleetDriveResult r;
        r.address = d ? d->address() : -1;
        m_results.append(r);
        m_transfers.append(nullptr);
    }
    if (m_drives.isEmpty()) {
        QMetaObject::invokeMethod(this, &FleetTransfer::finishIfDone, Qt::QueuedConnection);
        return;
    }
    startNext();
}

void FleetTransfer::startNext()
{
    // All at once, or one at a time.
    while (m_next < m_drives.size() && !m_stopping) {
        const int position = m_next++;
        startDrive(position);
        if (m_stopAtFirstFailure)
            return;
    }
    if (m_stopping) {
        for (; m_next < m_drives.size(); ++m_next) {
            m_results[m_next].state = FleetDriveResult::State::NotAttempted;
            emit driveFinished(m_next);
        }
    }
    finishIfDone();
}

void FleetTransfer::startDrive(int position)
{
    FleetDriveResult &r = m_results[position];
    r.state = FleetDriveResult::State::Running;
    auto *transfer = new ParameterTransfer(m_drives.at(position), this);
    m_transfers[position] = transfer;
    connect(transfer, &ParameterTransfer::finished, this,
            [this, position](const Error &error) { onDriveFinished(position, error); });
    emit driveStarted(position);
    if (m_job == Job::Backup)
        transfer->backup();
    else
        transfer->restore(m_files.isEmpty() ? m_file : m_files.at(position), m_options);
}

void FleetTransfer::onDriveFinished(int position, const Error &error)
{
    FleetDriveResult &r = m_results[position];
    if (r.isFinished())
        return; // aborted already
    const ParameterTransfer *t = m_transfers.at(position);
    if (const Drive *d = m_drives.at(position))
        r.identity = d->identity();
    r.values = t->driveValues();
    r.report = t->report();
    if (m_job == Job::Backup && !error)
        r.backup = t->backupFile();
    r.error = error;
    r.state = error ? FleetDriveResult::State::Failed : FleetDriveResult::State::Done;
    if (error)
        r.stoppedAt = ParameterTransfer::stageId(t->stage());
    emit driveFinished(position);
    int done = 0;
    for (const FleetDriveResult &x : std::as_const(m_results))
        done += x.isFinished() ? 1 : 0;
    emit progress(done, int(m_results.size()));
    if (error && m_stopAtFirstFailure)
        m_stopping = true;
    if (m_stopAtFirstFailure || m_stopping)
        startNext();
    else
        finishIfDone();
}

void FleetTransfer::cancel()
{
    if (!m_running)
        return;
    m_stopping = true;
    bool anyRunning = false;
    for (const FleetDriveResult &r : std::as_const(m_results))
        anyRunning = anyRunning || r.state == FleetDriveResult::State::Running;
    if (!anyRunning)
        startNext();
}

void FleetTransfer::abort(const Error &why)
{
    if (!m_running)
        return;
    m_stopping = true;
    m_abortError = why;
    for (int i = 0; i < m_results.size(); ++i) {
        FleetDriveResult &r = m_results[i];
        if (r.state == FleetDriveResult::State::Pending) {
            r.state = FleetDriveResult::State::NotAttempted;
            r.error = why;
            emit driveFinished(i);
        }
    }
    m_next = int(m_drives.size());
    // The drives under way fail on their own on a closed link, each with its report of what
    // it wrote; one that does not within the grace time is failed here.
    QTimer::singleShot(AbortGraceMs, this, [this] {
        for (int i = 0; i < m_results.size(); ++i) {
            FleetDriveResult &r = m_results[i];
            if (r.state != FleetDriveResult::State::Running)
                continue;
            const ParameterTransfer *t = m_transfers.at(i);
            if (const Drive *d = m_drives.at(i))
                r.identity = d->identity();
            r.values = t->driveValues();
            r.report = t->report();
            r.stoppedAt = ParameterTransfer::stageId(t->stage());
            r.error = m_abortError;
            r.state = FleetDriveResult::State::Failed;
            emit driveFinished(i);
        }
        finishIfDone();
    });
    finishIfDone();
}

bool FleetTransfer::allDone() const
{
    for (const FleetDriveResult &r : m_results)
        if (r.state != FleetDriveResult::State::Done)
            return false;
    return true;
}

void FleetTransfer::finishIfDone()
{
    if (!m_running)
        return;
    for (const FleetDriveResult &r : std::as_const(m_results))
        if (!r.isFinished())
            return;
    m_running = false;
    emit finished();
}

} // namespace dd
