#include "core/link/linkhealth.h"

#include <algorithm>
#include <cmath>

namespace dd {

namespace {
bool mentions(const QString &note, std::initializer_list<const char *> words)
{
    for (const char *w : words)
        if (note.contains(QLatin1String(w), Qt::CaseInsensitive))
            return true;
    return false;
}
} // namespace

bool LinkHealth::concerns(const TrafficRecord &r) const
{
    if (m_address < 0)
        return true;
    // A drop may hold any bytes (garbage, a frame of someone else): count it while a
    // request to this drive is out.
    if (r.direction == TrafficRecord::Direction::Discarded)
        return m_awaiting || !m_canOut.isEmpty();
    return !r.bytes.isEmpty() && quint8(r.bytes.at(0)) == m_address;
}

void LinkHealth::closeRequest()
{
    if (!m_awaiting)
        return;
    m_awaiting = false;
    if (m_crcSeen)
        ++m_counts.checksumErrors;
    else
        ++m_counts.timeouts;
}

void LinkHealth::answer(qint64 sentUs, qint64 atUs, int bytes)
{
    ++m_counts.answered;
    m_turnaroundsMs.append(double(atUs - sentUs) / 1000.0);
    if (m_baud > 0)
        m_maxWireUs = std::max(m_maxWireUs, int((m_txBytes + bytes) * 10 * 1000000LL / m_baud));
}

void LinkHealth::add(const TrafficRecord &r)
{
    if (!concerns(r))
        return;
    switch (r.direction) {
    case TrafficRecord::Direction::Tx:
        if (!r.isCan && !r.bytes.isEmpty() && r.bytes.at(0) == 0)
            return; // a broadcast expects no reply
        if (mentions(r.note, {"keep-alive", "heartbeat"}))
            return; // expects no reply either
        ++m_counts.requests;
        if (mentions(r.note, {"retry"}))
            ++m_counts.retries;
        if (mentions(r.note, {"not quiet"}))
            ++m_counts.busyLineSends;
        if (r.isCan) {
            for (qsizetype i = 0; i < m_canOut.size(); ++i) {
                if (m_canOut.at(i).bytes == r.bytes) { // asked again: the earlier one timed out
                    m_canOut.removeAt(i);
                    ++m_counts.timeouts;
                    break;
                }
            }
            m_canOut.append({r.timestampUs, r.bytes});
            return;
        }
        closeRequest();
        m_awaiting = true;
        m_crcSeen = false;
        m_txAtUs = r.timestampUs;
        m_txBytes = int(r.bytes.size());
        return;
    case TrafficRecord::Direction::Rx:
        if (r.isCan) {
            for (qsizetype i = 0; i < m_canOut.size(); ++i) {
                if (m_canOut.at(i).bytes.left(2) == r.bytes.left(2)) {
                    answer(m_canOut.at(i).atUs, r.timestampUs, 0);
                    m_canOut.removeAt(i);
                    return;
                }
            }
            return; // heartbeats and other unsolicited frames
        }
        if (!m_awaiting)
            return;
        m_awaiting = false;
        answer(m_txAtUs, r.timestampUs, int(r.bytes.size()));
        return;
    case TrafficRecord::Direction::Discarded:
        if (mentions(r.note, {"checksum", "crc"}))
            m_crcSeen = true;
        else if (mentions(r.note, {"stale", "late", "duplicat", "after the reply", "before request"}))
            ++m_counts.lateReplies;
        return;
    }
}

void LinkHealth::closeOutstanding()
{
    closeRequest();
    m_counts.timeouts += int(m_canOut.size());
    m_canOut.clear();
}

void LinkHealth::clear()
{
    *this = LinkHealth(m_baud);
}

LinkHealth::Summary LinkHealth::summary() const
{
    Summary s = m_counts;
    // A request still out at the end is not counted: its answer may be on its way.
    if (!m_turnaroundsMs.isEmpty()) {
        QList<double> t = m_turnaroundsMs;
        std::sort(t.begin(), t.end());
        s.minMs = t.first();
        s.maxMs = t.last();
        s.medianMs = t.size() % 2 ? t.at(t.size() / 2) : (t.at(t.size() / 2 - 1) + t.at(t.size() / 2)) / 2.0;
        // Twice the slowest turnaround beyond the wire time, at least 10 ms: a drive that
        // answered in x will rarely need more than 2x, and timer and adapter jitter add ms.
        const double beyondWire = std::max(0.0, s.maxMs - m_maxWireUs / 1000.0);
        s.recommendedTimeoutMs = std::max(10, int(std::ceil(2.0 * beyondWire)));
    }
    if (s.lateReplies > 0 || s.timeouts > 0)
        s.recommendedGapMs = int(std::ceil(std::max(s.maxMs, 1.0)));
    return s;
}

} // namespace dd
