#pragma once

#include "core/trend/samplebuffer.h"
#include "core/trend/trendchannel.h"
#include "core/trend/trendsnapshot.h"

#include <QMap>
#include <QObject>
#include <QStringList>
#include <memory>
#include <optional>
#include <vector>

namespace dd {

// Holds the recording of a trend: one SampleBuffer per channel. Whoever polls the drive
// feeds it with append(); views read the buffers (buffer()) or take snapshots.
//
// Pausing freezes the *view* only: a paused recorder keeps recording (append() works as
// ever) and remembers pausedAtUs(), the newest sample time when it was paused, so views
// can keep showing the window that ended there. clear() drops all samples but keeps the
// channels. The time origin is the first sample's time after construction or clear().
//
// No signal per sample (a sampler at 1 kHz would flood the event loop): views poll
// revision(), which changes on every append() and clear(). Lives in one thread.
class TrendRecorder : public QObject
{
    Q_OBJECT
public:
    explicit TrendRecorder(QObject *parent = nullptr);
    ~TrendRecorder() override;

    // Replaces the channel list. Channels kept (same id) keep their samples; channels no
    // longer listed lose theirs; new ones start empty.
    void setChannels(const QList<TrendChannel> &channels);
    // Adds a channel, or updates its name/unit when the id exists.
    void addChannel(const TrendChannel &channel);
    QList<TrendChannel> channels() const;
    QStringList channelIds() const;
    int channelCount() const { return static_cast<int>(m_channels.size()); }
    bool hasChannel(const QString &id) const { return indexOf(id) >= 0; }
    TrendChannel channel(const QString &id) const;       // empty channel if unknown
    const SampleBuffer *buffer(const QString &id) const; // nullptr if unknown

    // Records a sample. False if the channel is unknown or the time is older than the
    // channel's newest sample (see SampleBuffer); such samples count in rejectedCount().
    bool append(const QString &channelId, qint64 timeUs, double value);
    // All values of one reading (e.g. DriveReply::samples()) at the same time; returns
    // how many were recorded.
    int appendSamples(qint64 timeUs, const QMap<QString, double> &values);
    // Marks a gap at timeUs in every channel (a NaN sample, see SampleBuffer): the
    // recording lost the drive there (link lost, drive silent, recording stopped). A
    // channel whose newest sample is later gets the mark at that sample's time; a channel
    // whose newest sample already is a gap gets none. Returns how many channels got one.
    int appendGap(qint64 timeUs);
    // The value of a channel's plotted line at timeUs (SampleBuffer::lineValueAt()).
    std::optional<double> lineValueAt(const QString &channelId, qint64 timeUs) const;
    void clear();

    bool isPaused() const { return m_paused; }
    void setPaused(bool paused);
    qint64 pausedAtUs() const { return m_pausedAtUs; }

    bool isEmpty() const;
    bool hasOrigin() const { return m_hasOrigin; }
    qint64 originUs() const { return m_originUs; } // 0 until the first sample
    qint64 firstTimeUs() const;                    // oldest sample kept, any channel
    qint64 lastTimeUs() const;                     // newest sample, any channel
    quint64 revision() const { return m_revision; }
    quint64 rejectedCount() const { return m_rejected; }
    quint64 droppedCount() const; // evicted by the per-channel bound, all channels

    // Per-channel bound (SampleBuffer::DefaultCapacity unless changed); applies to all
    // channels, present and future.
    qsizetype capacityPerChannel() const { return m_capacity; }
    void setCapacityPerChannel(qsizetype capacity);
    qsizetype memoryBytes() const;

    // Copies of the samples with fromUs <= time <= toUs of the given channels (all when
    // `ids` is empty; unknown ids are skipped), in channel order.
    TrendSnapshot snapshot(qint64 fromUs, qint64 toUs, const QStringList &ids = {}) const;
    // Everything recorded.
    TrendSnapshot snapshotAll(const QStringList &ids = {}) const;

signals:
    void channelsChanged();
    void cleared();
    void pausedChanged(bool paused);

private:
    int indexOf(const QString &id) const;

    QList<TrendChannel> m_channels;
    std::vector<std::unique_ptr<SampleBuffer>> m_buffers; // parallel to m_channels
    qsizetype m_capacity = SampleBuffer::DefaultCapacity;
    bool m_paused = false;
    qint64 m_pausedAtUs = 0;
    bool m_hasOrigin = false;
    qint64 m_originUs = 0;
    quint64 m_revision = 0;
    quint64 m_rejected = 0;
};

} // namespace dd
