#include "core/tuning/capturerecorder.h"

#include <cmath>
#include <limits>

namespace dd {

namespace {
constexpr double Epsilon = 1e-9; // seconds: a sample exactly on a window's edge is inside
}

void CaptureRecorder::arm(const CaptureSettings &settings, const QStringList &channels)
{
    m_settings = settings;
    m_channels = channels;
    m_state = State::Filling;
    m_time.clear();
    m_columns = QVector<QVector<double>>(channels.size());
    m_begin = 0;
    m_havePrev = false;
    m_source.clear();
    m_triggerColumn = settings.trigger.isLevel() ? int(channels.indexOf(settings.trigger.channel)) : -1;
}

bool CaptureRecorder::feed(double t, const QVector<double> &values)
{
    if (m_state == State::Idle || m_state == State::Done)
        return false;
    if (m_state == State::Recording && t > m_triggerTime + m_settings.postSeconds() + Epsilon) {
        m_state = State::Done;
        return true;
    }
    if (m_time.size() == m_begin && m_state == State::Filling)
        m_firstTime = t;
    m_time.append(t);
    for (int c = 0; c < m_columns.size(); ++c)
        m_columns[c].append(c < values.size() ? values.at(c) : std::numeric_limits<double>::quiet_NaN());

    if (m_state == State::Filling && t - m_firstTime >= m_settings.preSeconds() - Epsilon) {
        m_state = State::Armed;
        m_armedAt = t;
        if (m_settings.trigger.kind == TriggerSpec::Kind::Now) {
            fire(t, QStringLiteral("now"));
            return false;
        }
    }
    if (m_state == State::Armed) {
        const double v = m_triggerColumn >= 0 && m_triggerColumn < values.size() ? values.at(m_triggerColumn)
                                                                                 : std::nan("");
        const double p = m_havePrev && m_triggerColumn >= 0 ? m_prev.value(m_triggerColumn, std::nan(""))
                                                            : std::nan("");
        if (m_triggerColumn >= 0 && m_settings.trigger.fires(p, v))
            fire(t, m_settings.trigger.toString());
        else if (m_settings.mode == CaptureSettings::Mode::Auto && t - m_armedAt >= m_settings.timeoutS - Epsilon)
            fire(t, QStringLiteral("timeout"));
        else
            dropBefore(t - m_settings.preSeconds());
    }
    m_prev = values;
    m_havePrev = true;
    if (m_state == State::Recording && m_settings.postSeconds() <= Epsilon) {
        m_state = State::Done;
        return true;
    }
    return false;
}

void CaptureRecorder::trigger(double t, const QString &source)
{
    if (m_state != State::Filling && m_state != State::Armed)
        return;
    fire(t, source);
}

bool CaptureRecorder::finish()
{
    if (m_state != State::Recording)
        return false;
    m_state = State::Done;
    return true;
}

void CaptureRecorder::fire(double t, const QString &source)
{
    m_state = State::Recording;
    m_triggerTime = t;
    m_source = source;
    dropBefore(t - m_settings.preSeconds());
}

void CaptureRecorder::dropBefore(double t)
{
    while (m_begin < m_time.size() && m_time.at(m_begin) < t - Epsilon)
        ++m_begin;
    // Compact now and then so that a long wait for the trigger does not grow the buffer.
    if (m_begin > 4096 && m_begin > m_time.size() / 2) {
        m_time.remove(0, m_begin);
        for (QVector<double> &c : m_columns)
            c.remove(0, m_begin);
        m_begin = 0;
    }
}

CaptureData CaptureRecorder::take()
{
    CaptureData d;
    if (m_state != State::Done)
        return d;
    d.channels = m_channels;
    d.triggerSource = m_source;
    const int n = int(m_time.size()) - m_begin;
    d.time.reserve(n);
    for (int i = m_begin; i < m_time.size(); ++i) {
        const double rel = m_time.at(i) - m_triggerTime;
        d.time.append(rel);
        if (rel < -Epsilon)
            ++d.preTriggerSamples;
    }
    d.columns.reserve(m_columns.size());
    for (const QVector<double> &c : std::as_const(m_columns))
        d.columns.append(c.mid(m_begin));
    d.interval = IntervalStats::of(d.time);
    d.gaps = CaptureGap::of(d.time);
    m_state = State::Idle;
    return d;
}

} // namespace dd
