#include "core/common/microtimer.h"

#include <QSocketNotifier>

#ifdef Q_OS_LINUX
#include <sys/timerfd.h>
#include <unistd.h>
#endif

namespace dd {

MicroTimer::MicroTimer(QObject *parent)
    : QObject(parent)
    , m_fallback(this)
{
    m_fallback.setSingleShot(true);
    m_fallback.setTimerType(Qt::PreciseTimer);
    connect(&m_fallback, &QTimer::timeout, this, [this] { onFired(false); });
#ifdef Q_OS_LINUX
    m_fd = ::timerfd_create(CLOCK_MONOTONIC, TFD_NONBLOCK | TFD_CLOEXEC);
    if (m_fd >= 0) {
        m_notifier = new QSocketNotifier(qintptr(m_fd), QSocketNotifier::Read, this);
        connect(m_notifier, &QSocketNotifier::activated, this, [this] { onFired(true); });
    }
#endif
}

MicroTimer::~MicroTimer()
{
#ifdef Q_OS_LINUX
    if (m_fd >= 0) {
        delete m_notifier;
        ::close(m_fd);
    }
#endif
}

void MicroTimer::start(qint64 waitUs)
{
    m_active = true;
#ifdef Q_OS_LINUX
    if (m_fd >= 0) {
        // A zero it_value would disarm the timer: the shortest wait is 1 µs.
        const qint64 us = waitUs < 1 ? 1 : waitUs;
        itimerspec spec{};
        spec.it_value.tv_sec = time_t(us / 1000000);
        spec.it_value.tv_nsec = long(us % 1000000) * 1000;
        if (::timerfd_settime(m_fd, 0, &spec, nullptr) == 0)
            return;
    }
#endif
    m_fallback.start(waitUs <= 0 ? 0 : int((waitUs + 999) / 1000));
}

void MicroTimer::stop()
{
    m_active = false;
    m_fallback.stop();
#ifdef Q_OS_LINUX
    if (m_fd >= 0) {
        const itimerspec disarm{};
        ::timerfd_settime(m_fd, 0, &disarm, nullptr);
    }
#endif
}

void MicroTimer::onFired(bool fromFd)
{
#ifdef Q_OS_LINUX
    if (fromFd) {
        quint64 expirations = 0;
        if (::read(m_fd, &expirations, sizeof expirations) != qint64(sizeof expirations))
            return; // spurious wake-up, or disarmed meanwhile
    }
#else
    Q_UNUSED(fromFd);
#endif
    if (!m_active)
        return;
    m_active = false;
    emit timeout();
}

} // namespace dd
