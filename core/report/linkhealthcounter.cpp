#include "core/report/linkhealthcounter.h"

#include "core/link/trafficrecord.h"
#include "core/link/traffictap.h"

namespace dd {

LinkHealthCounter::LinkHealthCounter(TrafficTap *tap, int baud, QObject *parent)
    : QObject(parent)
    , m_baud(baud)
{
    if (tap)
        connect(tap, &TrafficTap::frameRecorded, this, &LinkHealthCounter::count);
}

void LinkHealthCounter::count(const TrafficRecord &record)
{
    // The drive a request is for: its first data byte in every family (0: broadcast).
    if (record.direction == TrafficRecord::Direction::Tx && !record.bytes.isEmpty()) {
        const int address = quint8(record.bytes.at(0));
        if (address > 0 && !m_health.contains(address)) {
            LinkHealth h(m_baud);
            h.setAddress(address);
            m_health.insert(address, h);
        }
    }
    for (LinkHealth &h : m_health)
        h.add(record);
}

void LinkHealthCounter::closeOutstanding()
{
    for (LinkHealth &h : m_health)
        h.closeOutstanding();
}

RecordLinkHealth LinkHealthCounter::health(int address, const QString &scope) const
{
    const LinkHealth::Summary s = m_health.value(address, LinkHealth(m_baud)).summary();
    RecordLinkHealth h;
    h.measured = true;
    h.scope = scope;
    h.requests = s.requests;
    h.answered = s.answered;
    h.timeouts = s.timeouts;
    h.checksumErrors = s.checksumErrors;
    h.lateReplies = s.lateReplies;
    h.retries = s.retries;
    h.busyLineSends = s.busyLineSends;
    h.turnaroundMinMs = s.minMs;
    h.turnaroundMedianMs = s.medianMs;
    h.turnaroundMaxMs = s.maxMs;
    h.errors = m_errors.value(address);
    return h;
}

} // namespace dd
