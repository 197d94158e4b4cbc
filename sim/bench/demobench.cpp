#include "sim/bench/demobench.h"

#include "sim/bench/demobenchworker.h"

#include <QThread>

namespace dd {

DemoBench::DemoBench(QObject *parent)
    : QObject(parent)
{
    qRegisterMetaType<dd::Error>();
    bool ok = false;
    const double hz = qEnvironmentVariable("DRIVEDESK_DEMO_RESONANCE_HZ").toDouble(&ok);
    if (ok && hz >= 1.0 && hz <= 1000.0)
        m_resonanceHz = hz;
}

DemoBench::~DemoBench()
{
    stop();
}

Error DemoBench::start()
{
    if (m_running)
        return Error::none();
    m_thread = new QThread;
    m_thread->setObjectName(QStringLiteral("drivedesk-demobench"));
    m_worker = new DemoBenchWorker;
    m_worker->moveToThread(m_thread);
    // Queued to this (the caller's) thread: it runs after start() has returned.
    connect(m_worker, &DemoBenchWorker::ready, this, [this] {
        if (m_running && !m_ready) {
            m_ready = true;
            emit ready();
        }
    });
    connect(m_worker, &DemoBenchWorker::failed, this, &DemoBench::failed);
    m_thread->start();
    Error error;
    QMetaObject::invokeMethod(
        m_worker, [this, &error] { error = m_worker->build(Address, m_resonanceHz); }, Qt::BlockingQueuedConnection);
    if (error.isError()) {
        stop();
        return error;
    }
    m_connections = m_worker->connections();
    m_descriptions = m_worker->describe();
    m_alarmFamilies = m_worker->alarmFamilies();
    m_running = true;
    return Error::none();
}

void DemoBench::stop()
{
    if (!m_thread)
        return;
    // The simulators are deleted on their own thread (their sockets and timers live there).
    DemoBenchWorker *worker = m_worker;
    QMetaObject::invokeMethod(
        worker, [worker] { delete worker; }, Qt::BlockingQueuedConnection);
    m_worker = nullptr;
    m_thread->quit();
    m_thread->wait();
    delete m_thread;
    m_thread = nullptr;
    m_connections.clear();
    m_descriptions.clear();
    m_alarmFamilies.clear();
    m_running = false;
    m_ready = false;
}

bool DemoBench::injectAlarm(Family family, int code)
{
    if (!m_running)
        return false;
    bool ok = false;
    // The bench thread never waits for this one: blocking here is brief.
    QMetaObject::invokeMethod(
        m_worker, [this, family, code, &ok] { ok = m_worker->injectAlarm(family, Address, code); },
        Qt::BlockingQueuedConnection);
    return ok;
}

} // namespace dd
