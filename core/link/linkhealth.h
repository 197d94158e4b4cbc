#pragma once

#include "core/link/trafficrecord.h"

#include <QList>
#include <QtGlobal>

namespace dd {

// Link health of one drive, from the traffic already seen (the TrafficTap's records of the
// requests to it and its replies): turnaround, timeouts, checksum errors, late or
// duplicated replies, retries, and the reply allowance and inter-request gap it recommends.
// Fed by `drivedesk-cli ping` and the GUI's Link health view; no I/O of its own.
//
// A request is a TX record (not a broadcast, not a keep-alive); its turnaround runs to the RX
// record taken as its reply. On a serial link one request is out at a time: the next RX
// answers it, and a request with no RX before the next TX (or the end) went unanswered —
// a checksum error when a "bad checksum" / "CRC" drop came meanwhile, else a timeout. On
// CAN several requests are out at once: an RX answers the oldest outstanding request whose
// first two data bytes it shares (servo-can: station and read type; shuoke: address and
// command), and a request sent again with the same bytes while out means the earlier one
// timed out. The first data byte is the drive's address in every family. Drops the links
// mark as stale, late or duplicated count as late replies; a TX whose note says "retry"
// counts as a retry, one whose note says the line was "not quiet" as a busy-line send.
class LinkHealth
{
public:
    struct Summary
    {
        int requests = 0;
        int answered = 0;
        int timeouts = 0;
        int checksumErrors = 0;
        int lateReplies = 0; // stale, late or duplicated replies dropped
        int retries = 0;
        // Requests sent on a line that was never quiet (SerialLink's cap on waiting for
        // silence: another master, a babbling drive); a longer timeout or gap cannot help.
        int busyLineSends = 0;
        double minMs = 0, medianMs = 0, maxMs = 0; // turnaround, request sent to reply taken
        // The reply allowance beyond the wire time (--timeout) this drive needs with margin,
        // and the quiet time between requests (0: none needed; late replies seen: enough
        // for them to land first).
        int recommendedTimeoutMs = 0;
        int recommendedGapMs = 0;
    };

    // `baud` > 0: the serial baud rate (for the wire time in the recommendation); 0: CAN.
    explicit LinkHealth(int baud = 0)
        : m_baud(baud)
    {
    }

    // Keeps only records of `address` (the first data byte); -1 keeps all.
    void setAddress(int address) { m_address = address; }
    void add(const TrafficRecord &record);
    // Every request sent has been answered or given up on (the caller waited for all of
    // them: `ping`, a record the CLI made): one still out timed out, or was a checksum error.
    void closeOutstanding();
    void clear();
    Summary summary() const;

private:
    struct Outstanding
    {
        qint64 atUs = 0;
        QByteArray bytes;
    };
    bool concerns(const TrafficRecord &r) const;
    void closeRequest();
    void answer(qint64 sentUs, qint64 atUs, int bytes);

    int m_baud = 0;
    int m_address = -1;
    bool m_awaiting = false; // serial: a request is out
    bool m_crcSeen = false;
    qint64 m_txAtUs = 0;
    int m_txBytes = 0;
    int m_maxWireUs = 0;
    QList<Outstanding> m_canOut; // CAN: requests out, oldest first
    Summary m_counts;
    QList<double> m_turnaroundsMs;
};

} // namespace dd
