#include "ui/bus/etaestimator.h"

#include <QCoreApplication>
#include <cmath>

namespace dd {

void EtaEstimator::start()
{
    m_clock.start();
    m_done = 0;
    m_total = 0;
}

void EtaEstimator::update(int done, int total)
{
    if (done < m_done)
        start();
    m_done = done;
    m_total = total;
}

qint64 EtaEstimator::elapsedMs() const
{
    if (m_fixedElapsed >= 0)
        return m_fixedElapsed;
    return m_clock.isValid() ? m_clock.elapsed() : 0;
}

qint64 EtaEstimator::remainingMs() const
{
    if (m_done <= 0 || m_total <= 0)
        return -1;
    if (m_done >= m_total)
        return 0;
    return qint64(std::llround(double(elapsedMs()) / m_done * (m_total - m_done)));
}

QString EtaEstimator::format(qint64 ms)
{
    if (ms < 0)
        return QString();
    const qint64 s = (ms + 999) / 1000;
    if (s < 60)
        return QCoreApplication::translate("dd::EtaEstimator", "about %n s", nullptr, int(s));
    const qint64 min = (s + 30) / 60;
    return QCoreApplication::translate("dd::EtaEstimator", "about %n min", nullptr, int(min));
}

} // namespace dd
