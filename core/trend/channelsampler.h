#pragma once

#include "core/common/error.h"

#include <QElapsedTimer>
#include <QList>
#include <QMap>
#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QTimer>

namespace dd {

class Drive;
class DriveReply;

// Reads a drive's live values (Drive::readChannels) at a fixed rate, for trends and the
// CLI's monitor. While the link keeps up with the rate, one read goes out per tick. A tick
// that comes while a read is still out is skipped and counted (skippedCount(): the link is
// slower than the rate); the sampler then pipelines: it keeps up to maxPendingReads() (two)
// reads outstanding, so that the next request already waits in the link's queue when a
// reply comes in and the link never idles between samples (with one read at a time it
// would idle for the reply's trip to the sampler and the next request's trip back). It
// never queues more than that, so a stop or anything else asked of the drive waits behind
// at most two reads (stops jump the queue anyway: see the links' urgent requests).
// Samples are emitted in the order the reads went out; a reply that overtakes an earlier
// read is held until that one is in. Times are seconds since start(), taken when each reply
// arrives (a held one takes the time it is released, so times never go backwards). The
// first error stops sampling and is reported by failed(); after stop(), replies still on
// their way are ignored.
class ChannelSampler : public QObject
{
    Q_OBJECT
public:
    explicit ChannelSampler(Drive *drive, QObject *parent = nullptr);
    ~ChannelSampler() override;

    void setChannels(const QStringList &channelIds) { m_channels = channelIds; }
    QStringList channels() const { return m_channels; }
    void setIntervalMs(int ms);
    int intervalMs() const { return m_timer.interval(); }
    // Continuous: as fast as the link allows, whatever the interval — the next read is
    // asked for as soon as a reply is in, so that maxPendingReads() reads are always
    // outstanding (a tuning capture). Off by default: one read a tick, as above.
    void setContinuous(bool on) { m_continuous = on; }
    bool isContinuous() const { return m_continuous; }

    void start();
    void stop();
    bool isRunning() const { return m_running; }

    quint64 sampleCount() const { return m_samples; }
    quint64 skippedCount() const { return m_skipped; }
    double elapsedSeconds() const;
    // Reads asked of the drive and not answered yet (at most maxPendingReads()).
    int pendingReads() const;
    static constexpr int maxPendingReads() { return 2; }

signals:
    void sampled(double timeS, const QMap<QString, double> &values);
    void failed(const dd::Error &error);

private:
    struct Read
    {
        QPointer<DriveReply> reply;
        bool arrived = false;
        QMap<QString, double> values;
    };

    void tick();
    void read();
    void onReadFinished(DriveReply *reply);
    void fail(const Error &error);
    void forgetReads();

    QPointer<Drive> m_drive;
    QStringList m_channels;
    QTimer m_timer;
    QElapsedTimer m_clock;
    QList<Read> m_reads; // in the order they went out; arrived ones wait for earlier ones
    bool m_running = false;
    bool m_behind = false; // a tick found the reads outstanding: read again on a reply
    bool m_continuous = false;
    quint64 m_run = 0; // start() / stop() count: a handler sees a restart
    quint64 m_samples = 0;
    quint64 m_skipped = 0;
};

} // namespace dd
