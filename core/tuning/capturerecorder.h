#pragma once

#include "core/tuning/capturedata.h"
#include "core/tuning/capturesettings.h"

namespace dd {

// The capture engine, without I/O or clock: fed samples in arrival order, it keeps the
// pre-trigger window, watches the trigger and records until the record is full.
//
// Timing (docs/tuning.md): the trigger is watched only once the samples cover the whole
// pre-trigger window since arming, so that a capture always holds every sample of
// [trigger - pre, trigger + post] — none lost at the trigger, the pre-trigger exact to the
// sample. A level trigger fires on the first sample that satisfies it (that sample is time
// 0); an external trigger (alarm, motion start, manual, time-out) fires at the time given,
// the samples before it are pre-trigger. In auto mode a sample arriving `timeoutS` after
// the trigger became watchable fires it ("timeout").
class CaptureRecorder
{
public:
    enum class State { Idle, Filling, Armed, Recording, Done };

    // Starts over: nothing kept, waiting for the pre-trigger window to fill.
    void arm(const CaptureSettings &settings, const QStringList &channels);
    void reset() { m_state = State::Idle; }

    // One sample: arrival time (seconds, any origin, non-decreasing) and one value per
    // channel (NaN: not read). Returns true when this sample completed the capture.
    bool feed(double t, const QVector<double> &values);
    // An external trigger at time t (seconds, the samples' clock). Ignored unless armed;
    // while the pre-trigger window is still filling it fires too (manual force) and the
    // record simply has less before the trigger.
    void trigger(double t, const QString &source);
    // Ends a recording now, shorter than its record (a step test's axis is at rest): true
    // when there was one (state Done, take() it).
    bool finish();

    State state() const { return m_state; }
    bool isWatching() const { return m_state == State::Armed; }
    const CaptureSettings &settings() const { return m_settings; }
    // The finished capture (state Done); the recorder goes idle.
    CaptureData take();

private:
    void fire(double t, const QString &source);
    void dropBefore(double t);

    CaptureSettings m_settings;
    QStringList m_channels;
    State m_state = State::Idle;
    double m_firstTime = 0.0;
    double m_armedAt = 0.0; // when the trigger became watchable
    double m_triggerTime = 0.0;
    QString m_source;
    QVector<double> m_prev; // the previous sample's values (level triggers)
    bool m_havePrev = false;
    int m_triggerColumn = -1;

    QVector<double> m_time;
    QVector<QVector<double>> m_columns;
    int m_begin = 0; // first kept sample (older ones are dropped lazily)
};

} // namespace dd
