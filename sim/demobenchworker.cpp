#include "demobenchworker.h"

#include "ptyendpoint.h"
#include "simbench.h"
#include "simcanbus.h"

namespace dd {

DemoBenchWorker::DemoBenchWorker(QObject *parent)
    : QObject(parent)
{
}

DemoBenchWorker::~DemoBenchWorker()
{
    qDeleteAll(m_benches);
}

Error DemoBenchWorker::build(int address)
{
    if (!PtyEndpoint::isSupported())
        return {ErrorCode::NotSupported,
                tr("The demo bench needs pseudo-terminals, which this system does not offer.")};

    SimBenchOptions modbus;
    modbus.family = Family::ServoModbus;
    modbus.addresses = {address};
    modbus.demoMotion = true;
    SimBenchOptions can;
    can.family = Family::ServoCan;
    can.addresses = {address};
    can.can = QStringLiteral("virtualcan:auto");   // a private hub on a free port
    SimBenchOptions shuoke;
    shuoke.family = Family::Shuoke;
    shuoke.addresses = {address};
    shuoke.framing = QStringLiteral("rtu");

    for (const SimBenchOptions &o : {modbus, shuoke, can}) {
        auto *bench = new SimBench;
        const Error e = bench->start(o);
        if (e.code == ErrorCode::NotSupported && o.family == Family::Shuoke) {
            delete bench;   // a build without that family's simulator: demo the others
            continue;
        }
        if (e.isError()) {
            delete bench;
            return e;
        }
        m_benches.append(bench);
        m_connections.append(bench->clientSettings());
        m_descriptions.append(QStringLiteral("%1: %2").arg(familyId(o.family), bench->where()));
        if (SimCanBus *bus = bench->canBus()) {
            connect(bus, &SimCanBus::connected, this, &DemoBenchWorker::checkReady);
            connect(bus, &SimCanBus::errorOccurred, this, [this, bus](const QString &message) {
                if (!bus->isConnected())
                    emit failed({ErrorCode::OpenFailed, message});
            });
        }
    }
    // Reported from the event loop, after build() has returned, also when nothing waits.
    QMetaObject::invokeMethod(this, &DemoBenchWorker::checkReady, Qt::QueuedConnection);
    return Error::none();
}

void DemoBenchWorker::checkReady()
{
    if (m_readySent)
        return;
    for (SimBench *b : std::as_const(m_benches))
        if (b->canBus() && !b->canBus()->isConnected())
            return;
    m_readySent = true;
    emit ready();
}

} // namespace dd
