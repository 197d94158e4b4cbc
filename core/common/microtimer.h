#pragma once

#include <QObject>
#include <QTimer>

class QSocketNotifier;

namespace dd {

// A single-shot timer with microsecond resolution: the simulated buses' wire-timing model,
// and SerialLink's Modbus silences and probe timeouts (t3.5 is 1.75 ms at 115200 baud).
// QTimer counts whole milliseconds: a reply due in 2.7 ms would leave at 3 ms, up to a
// millisecond late — a quarter of a 45-byte frame at 115200 baud, or seven CAN frames at
// 1 Mbit/s. On Linux this is a timerfd (CLOCK_MONOTONIC) watched by a QSocketNotifier, so
// the event loop wakes when the time is due; elsewhere a Qt::PreciseTimer rounded up to the
// next millisecond (never early, as before). Lives in the thread that created it.
class MicroTimer : public QObject
{
    Q_OBJECT
public:
    explicit MicroTimer(QObject *parent = nullptr);
    ~MicroTimer() override;

    // Fires timeout() once, `waitUs` from now (at once, from the event loop, when <= 0).
    // Restarting replaces the pending time.
    void start(qint64 waitUs);
    void stop();
    bool isActive() const { return m_active; }
    // True when the microsecond timer is in use (Linux), false for the millisecond fallback.
    bool isPrecise() const { return m_fd >= 0; }

signals:
    void timeout();

private:
    void onFired(bool fromFd);

    int m_fd = -1;
    QSocketNotifier *m_notifier = nullptr;
    QTimer m_fallback;
    bool m_active = false;
};

} // namespace dd
