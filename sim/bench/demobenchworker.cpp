#include "sim/bench/demobenchworker.h"
#include "core/protocol/familytraits.h"
#include "sim/bench/simfamilies.h"

#include "sim/bench/simbench.h"
#include "sim/bus/ptyendpoint.h"
#include "sim/bus/simcanbus.h"

namespace dd {

DemoBenchWorker::DemoBenchWorker(QObject *parent)
    : QObject(parent)
{
}

DemoBenchWorker::~DemoBenchWorker()
{
    qDeleteAll(m_benches);
}

Error DemoBenchWorker::build(int address, double resonanceHz)
{
    if (!PtyEndpoint::isSupported())
        return {ErrorCode::NotSupported,
                tr("The demo bench needs pseudo-terminals, which this system does not offer.")};

    // One drive of each family, serial links first, each on its first framing.
    QList<SimBenchOptions> options;
    for (LinkKind link : {LinkKind::Serial, LinkKind::Can}) {
        for (const FamilyTraits *t : allFamilyTraits()) {
            if (t->framings.isEmpty() || t->framings.first().link != link)
                continue;
            SimBenchOptions o;
            o.family = t->family;
            o.addresses = {address};
            o.demoMotion = simFamily(t->family).demoMotion;
            o.resonanceHz = resonanceHz;
            if (t->framings.size() > 1)
                o.framing = t->framings.first().id;
            if (link == LinkKind::Can)
                o.can = QStringLiteral("virtualcan:auto"); // a private hub on a free port
            options << o;
        }
    }
    for (const SimBenchOptions &o : std::as_const(options)) {
        auto *bench = new SimBench;
        const Error e = bench->start(o);
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

QList<Family> DemoBenchWorker::alarmFamilies() const
{
    QList<Family> out;
    for (SimBench *b : m_benches)
        if (b->canInjectAlarm())
            out << b->options().family;
    return out;
}

bool DemoBenchWorker::injectAlarm(Family family, int address, int code)
{
    for (SimBench *b : std::as_const(m_benches))
        if (b->options().family == family && b->canInjectAlarm())
            return b->injectAlarm(address, code);
    return false;
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
