#include "trend/channelsampler.h"

#include "drive/drive.h"

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

void ChannelSampler::setIntervalMs(int ms)
{
    m_timer.setInterval(qMax(1, ms));
}

double ChannelSampler::elapsedSeconds() const
{
    return m_clock.isValid() ? double(m_clock.nsecsElapsed()) / 1e9 : 0.0;
}

void ChannelSampler::start()
{
    if (m_running)
        return;
    m_running = true;
    m_samples = 0;
    m_skipped = 0;
    m_behind = false;
    m_clock.start();
    m_timer.start();
    tick();
}

void ChannelSampler::stop()
{
    m_running = false;
    m_timer.stop();
}

void ChannelSampler::tick()
{
    if (!m_running)
        return;
    if (m_pending) {
        ++m_skipped;
        m_behind = true;
        return;
    }
    read();
}

void ChannelSampler::read()
{
    m_behind = false;
    if (!m_drive) {
        stop();
        emit failed({ErrorCode::LinkClosed, tr("The drive is gone; sampling stopped.")});
        return;
    }
    m_pending = true;
    DriveReply *reply = m_drive->readChannels(m_channels);
    connect(reply, &DriveReply::finished, this, [this, reply] {
        reply->deleteLater();
        m_pending = false;
        if (!m_running)
            return;
        if (!reply->ok()) {
            stop();
            emit failed(reply->error());
            return;
        }
        ++m_samples;
        const double timeS = elapsedSeconds();
        // Behind the rate: the next read goes out now, before the sample is handled.
        if (m_behind && m_drive)
            read();
        emit sampled(timeS, reply->samples());
    });
}

} // namespace dd
