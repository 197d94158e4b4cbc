#include "core/common/microtimer.h"

#include <QSocketNotifier>

#include <algorithm>

#ifdef Q_OS_LINUX
#include <sys/timerfd.h>
#include <time.h>
#include <unistd.h>
#endif

namespace dd {

namespace {
#ifdef Q_OS_LINUX
qint64 monotonicNs()
{
    timespec t{};
    ::clock_gettime(CLOCK_MONOTONIC, &t);
    return qint64(t.tv_sec) * 1000000000 + t.tv_nsec;
}
#endif
constexpr qint64 MaxEarlyWakeUs = 1000;
} // namespace

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

void MicroTimer::setEarlyWakeUs(qint64 us)
{
    m_earlyWakeUs = isPrecise() ? std::clamp<qint64>(us, 0, MaxEarlyWakeUs) : 0;
}

void MicroTimer::start(qint64 waitUs)
{
    m_active = true;
#ifdef Q_OS_LINUX
    if (m_fd >= 0) {
        qint64 sleepUs = waitUs;
        m_dueNs = 0;
        if (m_earlyWakeUs > 0) {
            m_dueNs = monotonicNs() + std::max<qint64>(waitUs, 0) * 1000;
            sleepUs = waitUs - m_earlyWakeUs;
        }
        // A zero it_value would disarm the timer: the shortest wait is 1 µs.
        const qint64 us = sleepUs < 1 ? 1 : sleepUs;
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
#ifdef Q_OS_LINUX
    if (fromFd && m_dueNs > 0) {
        // Woken early on purpose: wait out the rest awake (at most m_earlyWakeUs).
        while (monotonicNs() < m_dueNs) {
        }
    }
#endif
    m_active = false;
    emit timeout();
}

} // namespace dd
