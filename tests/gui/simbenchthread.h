#pragma once

// For the GUI tests: a SimBench on a thread of its own (as the demo bench runs), so that the
// test's GUI thread may block — a frozen window — without stalling the simulated drives.
// call() runs a function on the bench thread and returns its result.

#include "core/link/connectionsettings.h"
#include "sim/bench/simbench.h"
#include "sim/bus/simcanbus.h"
#include "sim/servocan/simservocandrive.h"

#include <QDeadlineTimer>
#include <QSignalSpy>
#include <QThread>
#include <QTimer>
#include <type_traits>

class SimBenchThread
{
public:
    SimBenchThread()
    {
        m_thread.setObjectName(QStringLiteral("test-simbench"));
        m_thread.start();
        m_context = new QObject;
        m_context->moveToThread(&m_thread);
    }

    ~SimBenchThread();

    template <typename F>
    auto call(F f)
    {
        using R = std::invoke_result_t<F>;
        if constexpr (std::is_void_v<R>) {
            QMetaObject::invokeMethod(m_context, f, Qt::BlockingQueuedConnection);
        } else {
            R result{};
            QMetaObject::invokeMethod(
                m_context, [&] { result = f(); }, Qt::BlockingQueuedConnection);
            return result;
        }
    }

    dd::Error start(const dd::SimBenchOptions &options)
    {
        return call([this, options] {
            m_bench = new dd::SimBench;
            return m_bench->start(options);
        });
    }

    // Only inside call().
    dd::SimBench *bench() const { return m_bench; }
    dd::SimServoCanDrive *canDrive(int index = 0) const
    {
        if (!m_bench || !m_bench->canBus())
            return nullptr;
        auto *d = dynamic_cast<dd::SimServoCanDrive *>(m_bench->canBus()->device(index));
        if (d)
            d->advanceTo(m_bench->canBus()->nowUs());
        return d;
    }

    dd::ConnectionSettings clientSettings()
    {
        return call([this] { return m_bench->clientSettings(); });
    }

    QObject *context() const { return m_context; }

private:
    QThread m_thread;
    QObject *m_context = nullptr;
    dd::SimBench *m_bench = nullptr;
};

inline SimBenchThread::~SimBenchThread()
{
    call([this] {
        delete m_bench;
        m_bench = nullptr;
    });
    m_thread.quit();
    m_thread.wait();
    delete m_context;
}

// Runs the event loop until `cond` holds (polled every few ms) or `timeoutMs` passes.
template <typename Cond>
bool waitUntil(Cond cond, int timeoutMs)
{
    QTimer tick;
    tick.start(5);
    QSignalSpy spy(&tick, &QTimer::timeout);
    QDeadlineTimer deadline(timeoutMs);
    while (!cond()) {
        if (deadline.hasExpired())
            return false;
        spy.wait(20);
    }
    return true;
}
