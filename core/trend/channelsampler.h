#pragma once

#include "common/error.h"

#include <QElapsedTimer>
#include <QMap>
#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QTimer>

namespace dd {

class Drive;

// Reads a drive's live values (Drive::readChannels) at a fixed rate, for trends and the
// CLI's monitor. One read is outstanding at a time: a tick that comes while the previous
// read is still on the wire is skipped and counted (the link is slower than the rate), so
// the sampler never queues up work; the next read then leaves as soon as that one is in,
// so a sampler asked for more than the link allows reads back to back (waiting for the
// next tick would lose up to an interval per sample). Times are seconds since start(),
// taken when each reply arrives. The first error stops sampling and is reported by
// failed().
class ChannelSampler : public QObject
{
    Q_OBJECT
public:
    explicit ChannelSampler(Drive *drive, QObject *parent = nullptr);

    void setChannels(const QStringList &channelIds) { m_channels = channelIds; }
    QStringList channels() const { return m_channels; }
    void setIntervalMs(int ms);
    int intervalMs() const { return m_timer.interval(); }

    void start();
    void stop();
    bool isRunning() const { return m_running; }

    quint64 sampleCount() const { return m_samples; }
    quint64 skippedCount() const { return m_skipped; }
    double elapsedSeconds() const;

signals:
    void sampled(double timeS, const QMap<QString, double> &values);
    void failed(const dd::Error &error);

private:
    void tick();
    void read();

    QPointer<Drive> m_drive;
    QStringList m_channels;
    QTimer m_timer;
    QElapsedTimer m_clock;
    bool m_running = false;
    bool m_pending = false;
    bool m_behind = false;     // a tick was skipped while the read was out
    quint64 m_samples = 0;
    quint64 m_skipped = 0;
};

} // namespace dd
