#include "core/report/linkhealthcounter.h"

#include "core/link/trafficrecord.h"
#include "core/link/traffictap.h"

namespace dd {

LinkHealthCounter::LinkHealthCounter(TrafficTap *tap, QObject *parent)
    : QObject(parent)
{
    if (tap)
        connect(tap, &TrafficTap::frameRecorded, this, &LinkHealthCounter::count);
}

void LinkHealthCounter::count(const TrafficRecord &record)
{
    switch (record.direction) {
    case TrafficRecord::Direction::Tx:
        ++m_health.framesSent;
        if (record.note.contains(QLatin1String("(retry ")))
            ++m_health.retries;
        break;
    case TrafficRecord::Direction::Rx: ++m_health.framesReceived; break;
    case TrafficRecord::Direction::Discarded: ++m_health.discarded; break;
    }
}

RecordLinkHealth LinkHealthCounter::health(const QString &scope) const
{
    RecordLinkHealth h = m_health;
    h.measured = true;
    h.scope = scope;
    return h;
}

} // namespace dd
