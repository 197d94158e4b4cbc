#include "core/tuning/commandwatch.h"

#include <cmath>

namespace dd {

void CommandWatch::idle()
{
    m_active = false;
}

void CommandWatch::expectSpeed(double speed, bool watchRunning)
{
    const bool wasActive = m_active;
    m_active = true;
    m_watchRunning = watchRunning;
    m_speed = speed;
    m_seenCommand = false;
    m_seenStatusBit = false;
    m_seenRunning = false;
    if (!wasActive)
        m_enableKnown = false; // the enable state is the one seen from the first command on
}

double CommandWatch::tolerance(double speed)
{
    return std::max(1.0, std::abs(speed) * 0.01);
}

QString CommandWatch::feedSample(const QMap<QString, double> &values)
{
    if (!m_active)
        return {};
    const double command = values.value(QStringLiteral("speed-command"), std::nan(""));
    if (std::isfinite(command)) {
        if (std::abs(command - m_speed) <= tolerance(m_speed))
            m_seenCommand = true;
        else if (m_seenCommand)
            return tr("the drive's speed command changed from %1 to %2").arg(m_speed).arg(command);
    }
    const double bits = values.value(QStringLiteral("status"), std::nan(""));
    if (m_watchRunning && std::isfinite(bits)) {
        const bool running = (qint64(bits) & StatusChannelBits::Running) != 0;
        if (running)
            m_seenStatusBit = true;
        else if (m_seenStatusBit)
            return tr("the drive reports that it stopped running");
    }
    return {};
}

QString CommandWatch::feedStatus(const DriveStatus &status)
{
    if (!m_active)
        return {};
    if (!m_enableKnown) {
        m_enableKnown = true;
        m_enabled = status.enabled;
    } else if (m_enabled && !status.enabled) {
        return tr("the drive was disabled");
    } else {
        m_enabled = status.enabled;
    }
    if (!m_watchRunning)
        return {};
    if (status.running)
        m_seenRunning = true;
    else if (m_seenRunning)
        return tr("the drive reports the axis at rest");
    return {};
}

} // namespace dd
