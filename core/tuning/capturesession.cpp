#include "core/tuning/capturesession.h"

#include "core/drive/drive.h"
#include "core/trend/channelsampler.h"

#include <cmath>

namespace dd {

CaptureSession::CaptureSession(Drive *drive, QObject *parent)
    : QObject(parent)
    , m_drive(drive)
    , m_sampler(new ChannelSampler(drive, this))
{
    connect(m_sampler, &ChannelSampler::sampled, this, &CaptureSession::onSample);
    connect(m_sampler, &ChannelSampler::failed, this, [this](const Error &e) {
        m_recorder.reset();
        emit failed(e);
    });
    if (drive) {
        connect(drive, &Drive::alarmChanged, this, [this](int code) {
            if (code != 0 && m_settings.trigger.kind == TriggerSpec::Kind::Alarm)
                m_recorder.trigger(now(), QStringLiteral("alarm"));
        });
    }
}

CaptureSession::~CaptureSession() = default;

void CaptureSession::start(const CaptureSettings &settings, const QStringList &channels)
{
    m_settings = settings;
    m_channels = channels;
    m_watchingSent = false;
    m_recorder.arm(settings, channels);
    m_sampler->setChannels(channels);
    m_sampler->setIntervalMs(1); // as fast as the link allows: the sampler pipelines and skips ticks
    m_sampler->start();
}

void CaptureSession::stop()
{
    m_sampler->stop();
    m_recorder.reset();
}

bool CaptureSession::isRunning() const
{
    return m_sampler->isRunning();
}

void CaptureSession::forceTrigger(const QString &source)
{
    m_recorder.trigger(now(), source);
}

double CaptureSession::now() const
{
    return m_sampler->elapsedSeconds();
}

quint64 CaptureSession::skippedTicks() const
{
    return m_sampler->skippedCount();
}

void CaptureSession::onSample(double timeS, const QMap<QString, double> &values)
{
    QVector<double> row;
    row.reserve(m_channels.size());
    for (const QString &c : std::as_const(m_channels))
        row.append(values.value(c, std::nan("")));
    const bool done = m_recorder.feed(timeS, row);
    emit sampled(timeS, values);
    if (m_recorder.state() == CaptureRecorder::State::Idle)
        return; // stopped by a receiver of sampled()
    if (!m_watchingSent && m_recorder.state() != CaptureRecorder::State::Filling) {
        m_watchingSent = true;
        emit watching();
    }
    if (!done || m_recorder.state() != CaptureRecorder::State::Done)
        return;
    const CaptureData data = m_recorder.take();
    if (m_settings.mode == CaptureSettings::Mode::Normal) {
        m_recorder.arm(m_settings, m_channels);
        m_watchingSent = false;
    } else {
        m_sampler->stop();
    }
    emit captured(data);
}

} // namespace dd
