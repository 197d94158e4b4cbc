#include "core/trend/channelsampler.h"

#include "core/drive/drive.h"

namespace dd {

ChannelSampler::ChannelSampler(Drive *drive, QObject *parent)
    : QObject(parent)
    , m_drive(drive)
    , m_timer(this)
{
    m_timer.setTimerType(Qt::PreciseTimer);
    m_timer.setInterval(100);
    connect(&m_timer, &QTimer::timeout, this, &ChannelSampler::tick);
}

ChannelSampler::~ChannelSampler()
{
    forgetReads();
}

void ChannelSampler::setIntervalMs(int ms)
{
    m_timer.setInterval(qMax(1, ms));
}

double ChannelSampler::elapsedSeconds() const
{
    return m_clock.isValid() ? double(m_clock.nsecsElapsed()) / 1e9 : 0.0;
}

int ChannelSampler::pendingReads() const
{
    int n = 0;
    for (const Read &r : m_reads)
        if (!r.arrived)
            ++n;
    return n;
}

void ChannelSampler::start()
{
    if (m_running)
        return;
    forgetReads();
    ++m_run;
    m_running = true;
    m_samples = 0;
    m_skipped = 0;
    m_behind = false;
    m_clock.start();
    m_timer.start();
    tick();
    if (m_continuous && m_running && pendingReads() < maxPendingReads())
        read();
}

void ChannelSampler::stop()
{
    m_running = false;
    m_timer.stop();
    ++m_run;
    forgetReads();
}

void ChannelSampler::forgetReads()
{
    // Replies still on their way are ignored (and deleted when they finish).
    for (const Read &r : std::as_const(m_reads))
        if (r.reply)
            disconnect(r.reply, nullptr, this, nullptr);
    m_reads.clear();
}

void ChannelSampler::fail(const Error &error)
{
    stop();
    emit failed(error);
}

void ChannelSampler::tick()
{
    if (!m_running)
        return;
    if (!m_drive) {
        fail({ErrorCode::LinkClosed, tr("The drive is gone; sampling stopped.")});
        return;
    }
    const int pending = pendingReads();
    if (pending == 0) {
        read();
        return;
    }
    // The link is slower than the rate: keep the next read waiting in its queue.
    ++m_skipped;
    if (pending < maxPendingReads())
        read();
    else
        m_behind = true;
}

void ChannelSampler::read()
{
    m_behind = false;
    if (!m_drive) {
        fail({ErrorCode::LinkClosed, tr("The drive is gone; sampling stopped.")});
        return;
    }
    DriveReply *reply = m_drive->readChannels(m_channels);
    connect(reply, &DriveReply::finished, reply, &QObject::deleteLater);
    connect(reply, &DriveReply::finished, this, [this, reply] { onReadFinished(reply); });
    m_reads.append(Read{reply, false, {}});
}

void ChannelSampler::onReadFinished(DriveReply *reply)
{
    if (!m_running)
        return;
    qsizetype at = 0;
    while (at < m_reads.size() && m_reads.at(at).reply != reply)
        ++at;
    if (at == m_reads.size())
        return;
    if (!reply->ok()) {
        fail(reply->error());
        return;
    }
    m_reads[at].arrived = true;
    m_reads[at].values = reply->samples();
    const double timeS = elapsedSeconds();
    // Behind the rate: the next read goes out now, before the sample is handled.
    if ((m_behind || m_continuous) && pendingReads() < maxPendingReads())
        read();
    const quint64 run = m_run;
    while (m_running && run == m_run && !m_reads.isEmpty() && m_reads.first().arrived) {
        const Read r = m_reads.takeFirst();
        ++m_samples;
        emit sampled(timeS, r.values);
    }
}

} // namespace dd
