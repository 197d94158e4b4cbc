#include "ui/shell/demolauncher.h"

#include "sim/bench/demobench.h"
#include "ui/bus/connectioncontroller.h"
#include "ui/bus/connectrequest.h"

namespace dd {

DemoLauncher::DemoLauncher(ConnectionController *connections, QObject *parent)
    : QObject(parent)
    , m_connections(connections)
{
}

DemoLauncher::~DemoLauncher() = default;

Error DemoLauncher::start()
{
    if (isRunning())
        return Error::none();
    auto bench = std::make_unique<DemoBench>();
    connect(bench.get(), &DemoBench::ready, this, &DemoLauncher::connectToBench);
    connect(bench.get(), &DemoBench::failed, this, &DemoLauncher::failed);
    if (Error e = bench->start())
        return e;
    m_bench = std::move(bench);
    emit started();
    return Error::none();
}

void DemoLauncher::connectToBench()
{
    for (const ConnectionSettings &s : m_bench->connections()) {
        ConnectRequest r;
        r.settings = s;
        r.scan = true;
        r.scanOptions.from = DemoBench::ScanFrom;
        r.scanOptions.to = DemoBench::ScanTo;
        // The simulator runs on a thread of a possibly busy machine: no tight timeouts.
        r.scanOptions.timeoutMs = 150;
        m_connections->connectTo(r);
    }
}

void DemoLauncher::stop()
{
    m_bench.reset();
}

bool DemoLauncher::isRunning() const
{
    return m_bench && m_bench->isRunning();
}

QList<ConnectionSettings> DemoLauncher::connections() const
{
    return m_bench ? m_bench->connections() : QList<ConnectionSettings>();
}

} // namespace dd
