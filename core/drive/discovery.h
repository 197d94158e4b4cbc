#pragma once

#include "core/common/error.h"
#include "core/drive/drivetypes.h"

#include <QList>
#include <QObject>

namespace dd {

struct ScanOptions
{
    int from = 1;
    int to = 247;
    QList<int> bauds;   // serial sweep; empty: the link's current baud only
    int timeoutMs = -1; // per probe; -1: adaptive (short, from the wire time)
    int listenMs = 300; // CAN: how long to listen for heartbeats / replies
};

// Finds drives of one family on an open link. start() returns at once; found() is emitted
// for each drive, progress() as the scan advances, finished() once at the end (also after
// cancel(), with ErrorCode::Cancelled). The link is left at the baud it was opened with.
class Discovery : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;
    virtual void start() = 0;
    virtual void cancel() = 0;
    const QList<DiscoveredDrive> &results() const { return m_results; }

signals:
    void found(const dd::DiscoveredDrive &drive);
    void progress(int done, int total);
    void finished(const dd::Error &error);

protected:
    void report(const DiscoveredDrive &d)
    {
        m_results.append(d);
        emit found(d);
    }

private:
    QList<DiscoveredDrive> m_results;
};

} // namespace dd
