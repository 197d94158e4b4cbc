#include "core/trend/trendrecorder.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dd {

TrendRecorder::TrendRecorder(QObject *parent)
    : QObject(parent)
{
}

TrendRecorder::~TrendRecorder() = default;

int TrendRecorder::indexOf(const QString &id) const
{
    for (int i = 0; i < m_channels.size(); ++i) {
        if (m_channels.at(i).id == id)
            return i;
    }
    return -1;
}

void TrendRecorder::setChannels(const QList<TrendChannel> &channels)
{
    QList<TrendChannel> newChannels;
    std::vector<std::unique_ptr<SampleBuffer>> newBuffers;
    for (const TrendChannel &c : channels) {
        if (c.id.isEmpty() || std::any_of(newChannels.cbegin(), newChannels.cend(), [&c](const TrendChannel &n) {
                return n.id == c.id;
            }))
            continue; // ids are unique and non-empty
        const int old = indexOf(c.id);
        newChannels.append(c);
        if (old >= 0)
            newBuffers.push_back(std::move(m_buffers[static_cast<size_t>(old)]));
        else
            newBuffers.push_back(std::make_unique<SampleBuffer>(m_capacity));
    }
    m_channels = newChannels;
    m_buffers = std::move(newBuffers);
    ++m_revision;
    emit channelsChanged();
}

void TrendRecorder::addChannel(const TrendChannel &channel)
{
    if (channel.id.isEmpty())
        return;
    const int i = indexOf(channel.id);
    if (i >= 0) {
        if (m_channels.at(i) == channel)
            return;
        m_channels[i] = channel;
    } else {
        m_channels.append(channel);
        m_buffers.push_back(std::make_unique<SampleBuffer>(m_capacity));
    }
    ++m_revision;
    emit channelsChanged();
}

QList<TrendChannel> TrendRecorder::channels() const
{
    return m_channels;
}

QStringList TrendRecorder::channelIds() const
{
    QStringList ids;
    for (const TrendChannel &c : m_channels)
        ids.append(c.id);
    return ids;
}

TrendChannel TrendRecorder::channel(const QString &id) const
{
    const int i = indexOf(id);
    return i >= 0 ? m_channels.at(i) : TrendChannel{};
}

const SampleBuffer *TrendRecorder::buffer(const QString &id) const
{
    const int i = indexOf(id);
    return i >= 0 ? m_buffers[static_cast<size_t>(i)].get() : nullptr;
}

bool TrendRecorder::append(const QString &channelId, qint64 timeUs, double value)
{
    const int i = indexOf(channelId);
    if (i < 0 || !m_buffers[static_cast<size_t>(i)]->append(timeUs, value)) {
        ++m_rejected;
        return false;
    }
    if (!m_hasOrigin) {
        m_hasOrigin = true;
        m_originUs = timeUs;
    }
    ++m_revision;
    return true;
}

int TrendRecorder::appendSamples(qint64 timeUs, const QMap<QString, double> &values)
{
    int n = 0;
    for (auto it = values.cbegin(); it != values.cend(); ++it)
        n += append(it.key(), timeUs, it.value()) ? 1 : 0;
    return n;
}

int TrendRecorder::appendGap(qint64 timeUs)
{
    int n = 0;
    for (auto &b : m_buffers) {
        if (b->isEmpty() || std::isnan(b->valueAt(b->size() - 1)))
            continue; // nothing to break yet, or already broken
        b->append(std::max(timeUs, b->lastTimeUs()), std::numeric_limits<double>::quiet_NaN());
        ++n;
    }
    if (n > 0)
        ++m_revision;
    return n;
}

std::optional<double> TrendRecorder::lineValueAt(const QString &channelId, qint64 timeUs) const
{
    const SampleBuffer *b = buffer(channelId);
    return b ? b->lineValueAt(timeUs) : std::nullopt;
}

void TrendRecorder::clear()
{
    for (auto &b : m_buffers)
        b->clear();
    m_hasOrigin = false;
    m_originUs = 0;
    m_pausedAtUs = 0;
    m_rejected = 0;
    ++m_revision;
    emit cleared();
}

void TrendRecorder::setPaused(bool paused)
{
    if (paused == m_paused)
        return;
    m_paused = paused;
    if (paused)
        m_pausedAtUs = isEmpty() ? m_originUs : lastTimeUs();
    ++m_revision;
    emit pausedChanged(paused);
}

bool TrendRecorder::isEmpty() const
{
    return std::all_of(m_buffers.cbegin(), m_buffers.cend(), [](const auto &b) { return b->isEmpty(); });
}

qint64 TrendRecorder::firstTimeUs() const
{
    qint64 t = std::numeric_limits<qint64>::max();
    for (const auto &b : m_buffers) {
        if (!b->isEmpty())
            t = std::min(t, b->firstTimeUs());
    }
    return t == std::numeric_limits<qint64>::max() ? m_originUs : t;
}

qint64 TrendRecorder::lastTimeUs() const
{
    qint64 t = std::numeric_limits<qint64>::min();
    for (const auto &b : m_buffers) {
        if (!b->isEmpty())
            t = std::max(t, b->lastTimeUs());
    }
    return t == std::numeric_limits<qint64>::min() ? m_originUs : t;
}

quint64 TrendRecorder::droppedCount() const
{
    quint64 n = 0;
    for (const auto &b : m_buffers)
        n += b->droppedCount();
    return n;
}

void TrendRecorder::setCapacityPerChannel(qsizetype capacity)
{
    m_capacity = std::max<qsizetype>(1, capacity);
    for (auto &b : m_buffers)
        b->setCapacity(m_capacity);
    ++m_revision;
}

qsizetype TrendRecorder::memoryBytes() const
{
    qsizetype n = 0;
    for (const auto &b : m_buffers)
        n += b->memoryBytes();
    return n;
}

TrendSnapshot TrendRecorder::snapshot(qint64 fromUs, qint64 toUs, const QStringList &ids) const
{
    TrendSnapshot snap;
    snap.originUs = m_originUs;
    snap.fromUs = fromUs;
    snap.toUs = toUs;
    const auto add = [&](int i) {
        snap.channels.append(m_channels.at(i));
        snap.series.append(m_buffers[static_cast<size_t>(i)]->samples(fromUs, toUs));
    };
    if (ids.isEmpty()) {
        for (int i = 0; i < m_channels.size(); ++i)
            add(i);
    } else {
        for (const QString &id : ids) {
            const int i = indexOf(id);
            if (i >= 0)
                add(i);
        }
    }
    return snap;
}

TrendSnapshot TrendRecorder::snapshotAll(const QStringList &ids) const
{
    TrendSnapshot snap = snapshot(std::numeric_limits<qint64>::min(), std::numeric_limits<qint64>::max(), ids);
    snap.fromUs = firstTimeUs();
    snap.toUs = lastTimeUs();
    return snap;
}

} // namespace dd
