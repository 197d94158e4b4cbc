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
//
// A sleeping thread wakes late: on the 2-core VM the benches run on, a timerfd's wake-up
// comes 66-78 us after the due time (median; 100-126 us at the 90th percentile, measured
// with a bare timerfd + poll loop: docs/performance.md, "Timer wake-ups"). Where a wire time
// is on every transaction's path (the Modbus silence before a request, the simulated wire's
// reply time), setEarlyWakeUs() wakes that much before the due time and waits out the rest
// awake, reading the clock: the timeout comes within a few microseconds of the due time at
// the cost of about (early wake - wake-up delay) of CPU per timeout. Off by default.
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
    // Wakes `us` before the due time and waits the rest awake (0, the default: off). Only
    // where precise; capped at 1 ms.
    void setEarlyWakeUs(qint64 us);
    // The early wake for a wire time: past the 90th percentile of the wake-up delay measured.
    static constexpr qint64 WireTimeEarlyWakeUs = 150;
    qint64 earlyWakeUs() const { return m_earlyWakeUs; }

signals:
    void timeout();

private:
    void onFired(bool fromFd);

    int m_fd = -1;
    QSocketNotifier *m_notifier = nullptr;
    QTimer m_fallback;
    bool m_active = false;
    qint64 m_earlyWakeUs = 0;
    qint64 m_dueNs = 0; // CLOCK_MONOTONIC, when this start() wakes early (else 0)
};

} // namespace dd
