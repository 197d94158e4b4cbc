#pragma once

#include "core/common/error.h"
#include "core/tuning/capturerecorder.h"

#include <QElapsedTimer>
#include <QObject>

namespace dd {

class DriveHub;

// A capture taken through the DriveHub (the GUI never touches a Drive): reads the channels
// as fast as the link answers — two reads in flight, so that the link never waits for the
// hand-over between the threads — and feeds each reading, in order, into a
// CaptureRecorder, timestamped when its reply reaches this thread (the I/O thread's hand-over
// adds well under a millisecond; the capture's interval statistics show what it was).
// forceTrigger() fires a manual trigger now; alarmRaised() fires an "alarm" trigger. Single
// and auto stop after one capture, normal re-arms.
class HubCapture : public QObject
{
    Q_OBJECT
public:
    HubCapture(DriveHub *hub, int connectionId, int address, QObject *parent = nullptr);

    void start(const CaptureSettings &settings, const QStringList &channels);
    void stop();
    bool isRunning() const { return m_running; }
    void forceTrigger(const QString &source = QStringLiteral("manual"));
    void alarmRaised();
    CaptureRecorder::State state() const { return m_recorder.state(); }
    const CaptureSettings &settings() const { return m_settings; }
    const QStringList &channels() const { return m_channels; }

signals:
    void stateChanged();
    void captured(const dd::CaptureData &capture);
    void failed(const dd::Error &error);

private:
    void readNext();
    double now() const { return double(m_clock.nsecsElapsed()) / 1e9; }

    DriveHub *m_hub;
    int m_connectionId;
    int m_address;
    CaptureRecorder m_recorder;
    CaptureSettings m_settings;
    QStringList m_channels;
    QElapsedTimer m_clock;
    bool m_running = false;
    static constexpr int MaxInFlight = 2;
    int m_inFlight = 0;
    quint64 m_generation = 0; // replies of an earlier start are dropped
};

} // namespace dd
