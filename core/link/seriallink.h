#pragma once

#include "core/common/error.h"
#include "core/common/microtimer.h"
#include "core/link/framematch.h"
#include "core/link/linkreply.h"
#include "core/link/serialsettings.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QQueue>
#include <QSerialPort>
#include <QSet>

#include <functional>
#include <optional>

namespace dd {

class TrafficTap;

// One request on a half-duplex serial bus.
struct SerialRequest
{
    QByteArray bytes;
    ReplyMatcher matcher;       // empty: no reply expected (broadcast, fire-and-forget)
    int expectedReplyBytes = 0; // for the timeout and the plausibility check
    int timeoutMs = -1;         // -1: wire time of request + reply + settings.responseTimeoutMs
    int retries = -1;           // -1: settings.retries
    QString note;               // shown in the trace
    bool urgent = false;        // stop / disable: ahead of every waiting ordinary request
    int peer = -1;              // the drive addressed, for the stale-reply rule; -1: any
    // After a timeout the line stays quiet this long (extended while bytes keep coming), so
    // that a late reply lands while nothing waits. -1: max(2 x timeout, 20 ms). A caller that
    // catches late replies itself (the Modbus scanner, from strayBytes) passes t3.5.
    qint64 quietAfterTimeoutUs = -1;
    // > 0: the request times out when no byte has come this long after it went out, without
    // waiting for the whole reply's wire time (scan probes: request + allowance). Once a byte
    // has come, the whole timeout applies.
    qint64 firstByteTimeoutUs = 0;
    // The line stays quiet this long after the transaction (a Modbus broadcast's turnaround).
    qint64 quietAfterUs = 0;
    // The words of a timeout, when the peer's protocol knows better than the link (which
    // address, what came instead): given the timeout in ms and the bytes that formed no
    // reply. Empty: the link's own message. Not used when a fast frame was dropped as stale.
    std::function<QString(int timeoutMs, const QByteArray &unmatched)> describeTimeout;
    QString describeCorrupt; // the words of a failed check; empty: the link's own
};

// Half-duplex request/reply transport on QSerialPort (RS485 / RS232).
//
// Requests queue and go out one at a time. Before each request whatever waits unread is
// read and reported as stray bytes (it is stale, and may be another drive's late answer);
// after each transaction the link keeps the line quiet for settings.minGapMs, and commands
// reach the drive at least settings.minCommandSpacingMs apart (last byte to last byte, plus
// CommandSpacingMarginUs; the count starts at the reply's first byte where there is a
// reply, which already lies the drive's latency after the command, so an adapter holding
// our bytes back cannot squeeze two commands). A reply is accepted only through the
// request's matcher. The stale-reply rule (docs/reliability.md): a frame that completes
// sooner than the wire allows (half the wire time of request plus reply) is taken for a
// stale answer, and dropped, only when one could be on its way: an earlier request to the
// same peer went unanswered (and nothing has paid that debt since), or the stale bytes set
// aside just before this request ended in the start of a frame. Dropping it pays the debt,
// so a fast peer (a pty, a socat pair, a USB adapter with a deep FIFO) loses at most one
// attempt; with nothing owed a fast reply is the answer. After a timeout the link also
// waits until the line has been quiet for the reply's wire time (plus margin) before it
// sends again; bytes that keep coming hold a request back at most LineBusyFactor times that
// quiet.
//
// Modbus RTU (ModbusLink) also sets an inter-frame silence (setInterFrameGapUs: t3.5), kept
// after the last byte seen on the line before each request, to the microsecond, and a
// function naming the peers whose complete frames are among stray bytes (setStrayPeers):
// such a frame pays that peer's debt wherever it lands. Bytes no request took are
// reported by strayBytes() (from the event loop).
//
// An urgent request (stop, disable) goes ahead of every waiting ordinary request, behind
// the urgent ones queued before it, right after the transaction on the wire now (which is
// never aborted; if it times out, its retries come first). The minimum gap and the quiet
// time after a timeout apply to it as to any request.
//
// The QSerialPort is created in open(), so the link may be moved to a worker thread first.
class SerialLink : public QObject
{
    Q_OBJECT
public:
    // Added to settings.minCommandSpacingMs: the drive's clock and our timer's wake-up (the
    // timer is to the microsecond and never early).
    static constexpr qint64 CommandSpacingMarginUs = 1000;
    // How long bytes that keep coming may hold a request back (the silence before it, the
    // quiet after a timeout), in multiples of the quiet after its timeout: see lineBusyLimitUs().
    static constexpr qint64 LineBusyFactor = 5;

    explicit SerialLink(QObject *parent = nullptr);
    ~SerialLink() override;

    void setTap(TrafficTap *tap) { m_tap = tap; }
    TrafficTap *tap() const { return m_tap; }

    bool open(const SerialSettings &settings, Error *error = nullptr);
    void close();
    bool isOpen() const;
    const SerialSettings &settings() const { return m_settings; }
    QString name() const { return m_settings.portName; }

    // Change the baud rate between transactions (scan sweeps); fails while busy.
    bool setBaudRate(qint32 baud);
    void setMinGapMs(int ms) { m_settings.minGapMs = ms; }
    void setMinCommandSpacingMs(int ms) { m_settings.minCommandSpacingMs = ms; }
    void setResponseTimeoutMs(int ms) { m_settings.responseTimeoutMs = ms; }
    void setRetries(int retries) { m_settings.retries = retries; }
    // Silence kept after the last byte on the line before a request, in microseconds
    // (Modbus t3.5). 0: none (only settings.minGapMs).
    void setInterFrameGapUs(qint64 us) { m_interFrameGapUs = std::max<qint64>(0, us); }
    qint64 interFrameGapUs() const { return m_interFrameGapUs; }
    // The silence before a request to the peer whose reply was the last thing on the line
    // (Modbus: 3.5 characters where setInterFrameGapUs keeps the spec's fixed 1.75 ms);
    // -1: none, every request waits interFrameGapUs(). When a request sent after this
    // shorter silence goes unanswered, the link keeps the full gap until it is reopened
    // (docs/reliability.md, "Silence between frames").
    void setSamePeerGapUs(qint64 us) { m_samePeerGapUs = us; }
    // The silence a request to the peer that has just answered waits now.
    qint64 samePeerGapUs() const;
    bool samePeerGapDropped() const { return m_samePeerGapDropped; }
    // The peers whose complete, check-valid frames are among `bytes` (see above).
    using StrayPeers = std::function<QList<int>(const QByteArray &bytes)>;
    void setStrayPeers(StrayPeers f) { m_strayPeers = std::move(f); }

    // Queue a request. The reply is parented to the link; delete it when done.
    LinkReply *send(const SerialRequest &request);
    // Fail every queued and pending request (e.g. the user pressed cancel).
    void cancelAll(const Error &why);

    int queuedCount() const { return m_queue.size() + (m_current ? 1 : 0); }
    bool isIdle() const { return !m_current && m_queue.isEmpty(); }
    quint64 timeoutCount() const { return m_timeouts; }
    quint64 retryCount() const { return m_retryCount; }
    quint64 checksumErrorCount() const { return m_checksumErrors; }
    quint64 staleReplyCount() const { return m_staleReplies; } // dropped as stale answers

    // Wire time of `bytes` characters at the current settings, in microseconds.
    qint64 wireTimeUs(qsizetype bytes) const;

signals:
    void opened();
    void closed(const dd::Error &reason); // by close() (no error) or because the port failed
    void idle();                          // queue drained
    // Bytes no request took: unsolicited or late bytes, bytes set aside before a request,
    // frames the awaited reply's matcher passed over, bytes that formed no reply before a
    // timeout. Typically a late reply to an earlier request. Emitted from the event loop.
    void strayBytes(const QByteArray &bytes);

private:
    struct Pending
    {
        SerialRequest request;
        QPointer<LinkReply> reply;
        int attempts = 0;
        bool droppedEarly = false;   // a frame of this request's shape was dropped as stale
        bool sentOnBusyLine = false; // an attempt went out before the line was quiet (lineBusyLimitUs())
    };
    enum class State { Idle, Gap, AwaitingReply, AwaitingWrite, Recovering };

    void scheduleNext();
    void transmit();
    void onReadyRead();
    void onBytes(const QByteArray &data);
    bool bytesWaitInDriver() const;                  // received, not yet read by the port (Unix)
    void anchorSpacingAtReply(qsizetype replyBytes); // command spacing counts from the reply's start
    void readWaitingBytes();                         // into the port's buffer now, for transmit() to set aside
    void processBuffer();
    void onResponseTimeout();
    void onGapElapsed();
    void onPortError(QSerialPort::SerialPortError error);
    void finishCurrent(const Error &error, const QByteArray &frame = {});
    void retryOrFail(const Error &error, qint64 quietUs);
    void enterRecovery(qint64 quietUs);
    void discardBuffer(const QString &why);
    void reportStray(const QByteArray &bytes);
    void payDebtsOf(const QByteArray &strayBytes);
    static bool endsInPartialFrame(const SerialRequest &request, QByteArray bytes);
    void armResponseTimer();
    qint64 nowUs() const { return m_clock.nsecsElapsed() / 1000; }
    int effectiveTimeoutMs(const SerialRequest &r) const;
    qint64 earliestSendUs(const SerialRequest &next); // notes in m_busyNote when the line kept it busy
    qint64 lineBusyLimitUs(const SerialRequest &next) const;
    bool sendsAfterShortGap(const SerialRequest &next) const;
    void failAll(const Error &why);

    SerialSettings m_settings;
    QSerialPort *m_port = nullptr;
    TrafficTap *m_tap = nullptr;
    QQueue<Pending> m_queue;
    std::optional<Pending> m_current;
    State m_state = State::Idle;
    QByteArray m_rx;
    MicroTimer m_responseTimer;
    MicroTimer m_gapTimer;
    QElapsedTimer m_clock;
    qint64 m_sentAtUs = 0;
    qint64 m_deadlineUs = 0;       // the whole timeout of the request in flight
    bool m_bytesSinceSend = false; // a byte came since the request went out
    qint64 m_interFrameGapUs = 0;
    qint64 m_samePeerGapUs = -1;
    int m_lastReplyPeer = -1;          // whose reply was the last thing on the line; -1: none
    bool m_shortGapForCurrent = false; // this attempt went out after the same-peer silence
    bool m_samePeerGapDropped = false; // a request after it went unanswered: full gap only
    QString m_gapNote;                 // for the trace of the next transmission
    QString m_busyNote;                // the same: bytes kept the line busy (earliestSendUs())
    StrayPeers m_strayPeers;
    int m_deferrals = 0;            // a send or a timeout waited for the port to read what came
    qint64 m_quietUntilUs = 0;      // no transmission before this (gap / recovery)
    qint64 m_lastCommandEndUs = -1; // when the last command's last byte left (estimated)
    qint64 m_lastRxUs = 0;
    qint64 m_recoveryQuietUs = 0;
    qint64 m_waitingSinceUs = -1;     // since when the request at the head has been waiting to go out
    bool m_lateForCurrent = false;    // bytes came between attempts of the current request
    bool m_flushedForCurrent = false; // stale bytes were set aside just before this attempt
    bool m_readingAside = false;      // readWaitingBytes() is reading: onReadyRead() leaves them
    QSet<int> m_owed;                 // peers whose last request went unanswered
    quint64 m_staleReplies = 0;
    qint64 m_lastEarlyUs = 0;     // the last frame dropped as stale: after how long, and the
    qint64 m_lastEarlyNeedUs = 0; // wire time request + reply needed
    quint64 m_timeouts = 0;
    quint64 m_retryCount = 0;
    quint64 m_checksumErrors = 0;
};

} // namespace dd
