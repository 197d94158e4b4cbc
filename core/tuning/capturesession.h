#pragma once

#include "core/common/error.h"
#include "core/tuning/capturerecorder.h"

#include <QObject>
#include <QPointer>

namespace dd {

class ChannelSampler;
class Drive;

// A capture on a live drive: samples the channels as fast as the link allows (the trend's
// ChannelSampler, pipelined, each sample timestamped by its arrival) into a CaptureRecorder.
// An alarm the drive reports fires an "alarm" trigger; forceTrigger() fires a manual one
// (and a step test fires "motion" when it sends its command). Single and auto modes stop
// after one capture; normal re-arms.
class CaptureSession : public QObject
{
    Q_OBJECT
public:
    explicit CaptureSession(Drive *drive, QObject *parent = nullptr);
    ~CaptureSession() override;

    void start(const CaptureSettings &settings, const QStringList &channels);
    void stop();
    bool isRunning() const;
    // Fires the trigger now (on the samples' clock).
    void forceTrigger(const QString &source = QStringLiteral("manual"));
    // Seconds on the samples' clock.
    double now() const;
    CaptureRecorder::State state() const { return m_recorder.state(); }
    quint64 skippedTicks() const;

signals:
    void watching(); // the pre-trigger window is full: the trigger is watched from now on
    void captured(const dd::CaptureData &capture);
    // Every sample as it arrives (seconds on the samples' clock, value per channel).
    void sampled(double timeS, const QMap<QString, double> &values);
    void failed(const dd::Error &error);

private:
    void onSample(double timeS, const QMap<QString, double> &values);

    QPointer<Drive> m_drive;
    ChannelSampler *m_sampler = nullptr;
    CaptureRecorder m_recorder;
    CaptureSettings m_settings;
    QStringList m_channels;
    bool m_watchingSent = false;
};

} // namespace dd
