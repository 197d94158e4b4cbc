#pragma once

#include "core/drive/discovery.h"
#include "core/link/modbuslink.h"

#include <QElapsedTimer>
#include <QHash>
#include <QList>
#include <QPointer>
#include <QSet>

namespace dd {

class LinkReply;

// Finds servo-modbus drives: for each baud rate of ScanOptions::bauds (baud-major, so the
// port is reopened once per rate), asks every address of from..to that has not answered yet
// for PA2 (one register: the firmware version, reported with the drive).
//
// Per-probe timeout (ScanOptions::timeoutMs = -1): no first byte by the end of the request
// + an allowance, or no whole reply by the wire time of request and 7-byte reply + the
// allowance (ModbusRequest::firstByteTimeoutUs). The allowance is 4 ms (or setAllowanceMs)
// until a drive answered, then twice the drives' turnaround, at least the turnaround + 1 ms
// (the quickest turnaround
// seen: one answer slowed by a busy host must not slow every later probe; a drive that is
// always slower is asked again, below). The round trip it comes from runs from the request
// leaving for the port to the reply's last byte. After a silent address the line is quiet
// only t3.5 (ModbusRequest::quietAfterTimeoutUs): late replies are caught here. A drive
// behind a slow USB adapter (latency timer 16 ms) is found through that too, or faster with
// an explicit timeout (e.g. 40 ms), which is then the whole timeout. No retries, except one
// repeat of a probe whose reply was garbled. An exception reply also counts as "a device
// answers here" (state "exception <code>").
// A reply that comes after its probe's timeout is not lost: a CRC-valid answer among the
// link's stray bytes (ModbusLink::strayBytes) from an address whose probe timed out has
// that address asked once more with the link's normal timeout. The sweep at a baud ends
// finalWaitMs() after its last probe timed out, so that the last one can be rescued too:
// 2 probe timeouts, at least 50 ms, and at least twice the latest any late reply of this
// scan came after its probe (at most 1 s): a slow peer's neighbours are likely as slow
// (pymodbus on a pty answers in 5-90 ms, far past a 115200-baud probe's few ms, while
// the turnaround the probes are sized from may come from a quick answer).
// Probes are queued two at a time, so that the link sends the next one without waiting for
// this object; the link keeps t3.5 of silence before each.
// The link is left at its original baud; cancel() stops at once (finished(Cancelled)).
class ServoModbusScanner : public Discovery
{
    Q_OBJECT
public:
    static constexpr int DefaultAllowanceMs = 4;
    static constexpr int MinFinalWaitMs = 50;
    static constexpr int MaxFinalWaitMs = 1000; // the most a late reply can teach

    ServoModbusScanner(ModbusLink *link, const ScanOptions &options, QObject *parent = nullptr);
    ~ServoModbusScanner() override;

    void start() override;
    void cancel() override;

    void setAllowanceMs(int ms)
    {
        m_baseAllowanceUs = qint64(ms) * 1000;
        m_allowanceSet = true;
    }
    int allowanceMs() const;
    qint64 firstByteTimeoutUs() const; // a probe's: request + allowance (0: none)
    int probeTimeoutMs() const;        // at the link's current baud
    int finalWaitMs() const;           // after the last probe at a baud, when it timed out
    int probesSent() const { return m_probesSent; }
    bool isRunning() const { return m_running; }

private:
    void startBaud();
    void fillWindow();
    enum class Probe { First, Repeat, Rescue };
    void sendProbe(int address, Probe kind);
    void onProbeFinished(LinkReply *reply, int address, Probe kind);
    void onStrayBytes(const QByteArray &bytes);
    bool findLateReplies(); // in m_stray, from timed-out addresses: queued to be asked again
    void finishBaud();
    void noteTurnaround(qint64 us);
    qint64 allowanceUs() const;
    void endScan(const Error &error);

    QPointer<ModbusLink> m_link;
    ScanOptions m_options;
    QList<int> m_bauds;
    int m_baudIndex = -1;
    int m_originalBaud = 0;
    QList<int> m_unprobed; // addresses still to probe at this baud
    QList<int> m_repeat;   // garbled replies: probe once more
    QList<int> m_rescue;   // late replies: probe once more with the normal timeout
    QSet<int> m_timedOut;  // at this baud
    QSet<int> m_rescued;   // at this baud
    QByteArray m_stray;    // recent stray bytes, searched for late replies
    QSet<int> m_found;
    QList<QPointer<LinkReply>> m_inFlight;
    int m_done = 0;
    int m_total = 0;
    int m_probesSent = 0;
    qint64 m_baseAllowanceUs = qint64(DefaultAllowanceMs) * 1000;
    qint64 m_turnaroundUs = 0; // drive turnaround the allowance is sized from
    QElapsedTimer m_clock;
    QHash<int, qint64> m_probeSentUs; // at this baud: address -> its first probe was queued
    qint64 m_latestReplyUs = 0;       // the latest a late reply came after its probe
    bool m_turnaroundSeen = false;
    bool m_allowanceSet = false; // setAllowanceMs(): fixed, not learned
    bool m_lastTimedOut = false; // the last finished probe timed out
    bool m_finishingBaud = false;
    bool m_running = false;
};

} // namespace dd
