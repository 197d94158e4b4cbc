#include "core/link/seriallink.h"

#include "core/common/timerslack.h"
#include "core/link/serialaccess.h"
#include "core/link/traffictap.h"
#include "core/link/urgentqueue.h"

#include <QCoreApplication>
#include <QLoggingCategory>
#include <cmath>

#ifdef Q_OS_UNIX
#include <sys/ioctl.h>
#endif

Q_LOGGING_CATEGORY(lcSerialLink, "drivedesk.link.serial")

namespace dd {

namespace {
constexpr qsizetype kMaxRxBuffer = 4096;
constexpr int kDefaultReplyBytes = 8;
constexpr int MaxDeferrals = 8; // waits for the port to read what its driver holds
constexpr qint64 DeferralUs = 100;

} // namespace

SerialLink::SerialLink(QObject *parent)
    : QObject(parent)
    , m_responseTimer(this)
    , m_gapTimer(this)
{
    connect(&m_responseTimer, &MicroTimer::timeout, this, &SerialLink::onResponseTimeout);
    connect(&m_gapTimer, &MicroTimer::timeout, this, &SerialLink::onGapElapsed);
    // The silence before a request is on every transaction's path: end it on time.
    m_gapTimer.setEarlyWakeUs(MicroTimer::WireTimeEarlyWakeUs);
    m_clock.start();
}

SerialLink::~SerialLink()
{
    failAll({ErrorCode::Cancelled, tr("The serial link was destroyed.")});
}

bool SerialLink::open(const SerialSettings &settings, Error *error)
{
    if (m_port)
        close();
    m_settings = settings;
    auto *port = new QSerialPort(this);
    port->setPortName(settings.portName);
    port->setBaudRate(settings.baud);
    port->setDataBits(settings.dataBits);
    port->setParity(settings.parity);
    port->setStopBits(settings.stopBits);
    port->setFlowControl(QSerialPort::NoFlowControl);
    if (!port->open(QIODevice::ReadWrite)) {
        Error e{ErrorCode::OpenFailed,
                tr("Cannot open serial port %1: %2. Check the device name, that no other "
                   "program is using it, and that you may access it (dialout group).")
                    .arg(settings.portName, port->errorString())};
        if (const auto denied = serialAccessProblem(settings.portName))
            e.message = denied->message();
        delete port;
        if (error)
            *error = e;
        return false;
    }
    port->clear();
    m_port = port;
    tightenTimerSlack(); // the minimum gap is on every transaction's path
    m_rx.clear();
    m_quietUntilUs = 0;
    m_waitingSinceUs = -1;
    m_lastCommandEndUs = -1;
    m_lastReplyPeer = -1;
    m_samePeerGapDropped = false;
    m_owed.clear();
    connect(m_port, &QSerialPort::readyRead, this, &SerialLink::onReadyRead);
    connect(m_port, &QSerialPort::errorOccurred, this, &SerialLink::onPortError);
    qCDebug(lcSerialLink) << "opened" << settings.portName << settings.baud;
    emit opened();
    return true;
}

void SerialLink::close()
{
    if (!m_port)
        return;
    failAll({ErrorCode::Cancelled, tr("The serial port %1 was closed.").arg(m_settings.portName)});
    m_port->disconnect(this);
    m_port->close();
    m_port->deleteLater();
    m_port = nullptr;
    emit closed(Error::none());
}

bool SerialLink::isOpen() const
{
    return m_port && m_port->isOpen();
}

bool SerialLink::setBaudRate(qint32 baud)
{
    if (!isIdle() || !m_port)
        return false;
    if (!m_port->setBaudRate(baud))
        return false;
    m_settings.baud = baud;
    m_port->clear();
    m_rx.clear();
    m_owed.clear(); // whatever was owed was sent at the other baud rate
    m_lastReplyPeer = -1;
    return true;
}

qint64 SerialLink::wireTimeUs(qsizetype bytes) const
{
    const double baud = m_settings.baud > 0 ? m_settings.baud : 9600;
    return static_cast<qint64>(std::ceil(bytes * m_settings.bitsPerChar * 1e6 / baud));
}

LinkReply *SerialLink::send(const SerialRequest &request)
{
    auto *reply = new LinkReply(this);
    if (!isOpen()) {
        reply->finishWithError({ErrorCode::LinkClosed, tr("The serial port is not open.")});
        return reply;
    }
    enqueueByUrgency(m_queue, Pending{request, reply, 0});
    if (m_state == State::Idle)
        scheduleNext();
    return reply;
}

void SerialLink::cancelAll(const Error &why)
{
    failAll(why);
}

void SerialLink::failAll(const Error &why)
{
    m_responseTimer.stop();
    m_gapTimer.stop();
    if (m_current) {
        if (m_state == State::AwaitingReply) {
            // Aborted in flight: its answer may still come (the stale-reply rule), and the
            // line stays quiet as after a timeout.
            m_owed.insert(m_current->request.peer);
            const qint64 quiet = m_current->request.quietAfterTimeoutUs >= 0
                ? m_current->request.quietAfterTimeoutUs
                : qint64(std::max(2 * effectiveTimeoutMs(m_current->request), 20)) * 1000;
            enterRecovery(quiet);
        }
        if (m_current->reply)
            m_current->reply->finishWithError(why);
        m_current.reset();
    }
    while (!m_queue.isEmpty()) {
        Pending p = m_queue.dequeue();
        if (p.reply)
            p.reply->finishWithError(why);
    }
    m_state = State::Idle;
}

void SerialLink::scheduleNext()
{
    if (m_current && m_state != State::Gap)
        return;
    if (!m_current) {
        // Skip requests whose caller has already given up.
        while (!m_queue.isEmpty() && !m_queue.head().reply)
            m_queue.dequeue();
        if (m_queue.isEmpty()) {
            m_state = State::Idle;
            emit idle();
            return;
        }
    }
    const qint64 now = nowUs();
    if (m_waitingSinceUs < 0)
        m_waitingSinceUs = now;
    const qint64 earliest = earliestSendUs(m_current ? m_current->request : m_queue.head().request);
    if (now < earliest) {
        m_state = State::Gap;
        m_gapTimer.start(earliest - now);
        return;
    }
    if (!m_current) {
        m_current = m_queue.dequeue();
        m_lateForCurrent = false;
    }
    transmit();
}

qint64 SerialLink::earliestSendUs(const SerialRequest &next)
{
    qint64 earliest = m_quietUntilUs;
    const qint64 gap = sendsAfterShortGap(next) ? samePeerGapUs() : m_interFrameGapUs;
    if (gap > 0 && m_lastRxUs > 0)
        earliest = std::max(earliest, m_lastRxUs + gap); // silence since the last byte
    // Bytes that keep coming push the silence on; a line that is never quiet (another master,
    // a babbling drive) must not hold the request for ever: after lineBusyLimitUs() of
    // waiting it goes out anyway, and the trace says why.
    const qint64 limit = m_waitingSinceUs + lineBusyLimitUs(next);
    m_busyNote.clear();
    if (m_waitingSinceUs >= 0 && earliest > limit) {
        earliest = limit;
        m_busyNote = QStringLiteral("the line was not quiet for %1 ms: sent anyway")
                         .arg((limit - m_waitingSinceUs) / 1000);
    }
    if (m_settings.minCommandSpacingMs > 0 && m_lastCommandEndUs >= 0) {
        // The drive counts from each command it receives, i.e. from its last byte.
        const qint64 nextEnd = m_lastCommandEndUs + qint64(m_settings.minCommandSpacingMs) * 1000
            + CommandSpacingMarginUs;
        earliest = std::max(earliest, nextEnd - wireTimeUs(next.bytes.size()));
    }
    return earliest;
}

qint64 SerialLink::lineBusyLimitUs(const SerialRequest &next) const
{
    // Five times the quiet kept after a timeout of this request (twice its timeout, at
    // least 20 ms): 500 ms at the default 50 ms timeout.
    const qint64 quiet = std::max(2 * qint64(effectiveTimeoutMs(next)), qint64(20)) * 1000;
    return LineBusyFactor * std::max(quiet, m_recoveryQuietUs);
}

qint64 SerialLink::samePeerGapUs() const
{
    return m_samePeerGapUs >= 0 && !m_samePeerGapDropped ? std::min(m_samePeerGapUs, m_interFrameGapUs)
                                                         : m_interFrameGapUs;
}

bool SerialLink::sendsAfterShortGap(const SerialRequest &next) const
{
    return next.peer >= 0 && next.peer == m_lastReplyPeer && samePeerGapUs() < m_interFrameGapUs;
}

void SerialLink::onGapElapsed()
{
    scheduleNext();
}

void SerialLink::transmit()
{
    if (!m_port) {
        failAll({ErrorCode::LinkClosed, tr("The serial port is not open.")});
        return;
    }
    if (bytesWaitInDriver() && m_deferrals < MaxDeferrals) {
        // Bytes came that the port has not read yet (a late answer, a duplicate): let them
        // be read and shown first, and the silence before the request count from them.
        ++m_deferrals;
        m_state = State::Gap;
        m_gapTimer.start(DeferralUs);
        return;
    }
    m_deferrals = 0;
    // Whatever waits unread answers no request of ours (a duplicate, a late answer): read
    // after the request went out it could pass for its answer. It is read now, shown in the
    // trace and reported (strayBytes), never dropped unseen: a late answer of another peer
    // is how a scan finds a slow drive. (Flushing the driver's input here lost the frames
    // that landed after the check above: tst_seriallink framesOfOtherPeersAreNeverDroppedUnseen.)
    readWaitingBytes();
    if (!m_port || !m_current)
        return; // the port failed while reading: onPortError() failed every request
    Pending &p = *m_current;
    ++p.attempts;
    m_rx += m_port->readAll(); // the port's buffer, with what readWaitingBytes() put there
    m_flushedForCurrent = false;
    if (!m_rx.isEmpty()) {
        // Stale bytes just before this request: when they end in the start of a frame, its
        // rest may come right after the request and pass for a fast answer. Complete frames
        // (a late answer, a duplicate) and noise predict nothing.
        m_flushedForCurrent = endsInPartialFrame(p.request, m_rx);
        payDebtsOf(m_rx);
        reportStray(m_rx);
        discardBuffer(QStringLiteral("stale bytes before request"));
    }
    m_recoveryQuietUs = 0;
    m_waitingSinceUs = -1;
    m_bytesSinceSend = false;
    m_shortGapForCurrent = sendsAfterShortGap(p.request);
    m_lastReplyPeer = -1; // until this request's reply is the last thing on the line
    if (m_tap) {
        QString note = p.request.note;
        if (p.attempts > 1)
            note = QStringLiteral("%1 (retry %2)").arg(note).arg(p.attempts - 1).trimmed();
        for (const QString &why : {m_gapNote, m_busyNote})
            if (!why.isEmpty())
                note = QStringLiteral("%1 (%2)").arg(note, why).trimmed();
        m_tap->recordSerial(TrafficRecord::Direction::Tx, m_settings.portName, p.request.bytes, note);
    }
    if (!m_busyNote.isEmpty())
        p.sentOnBusyLine = true;
    m_gapNote.clear();
    m_busyNote.clear();
    m_port->write(p.request.bytes);
    // To the driver now, not on the next event-loop pass. A failing port reports it from
    // inside flush() (or the read above): onPortError() has then failed every request and
    // dropped the port.
    m_port->flush();
    if (!m_port || !m_current)
        return;
    m_sentAtUs = nowUs();
    m_lastCommandEndUs = m_sentAtUs + wireTimeUs(p.request.bytes.size());
    if (!p.request.matcher) {
        m_state = State::AwaitingWrite;
        m_responseTimer.start(std::max<qint64>(1, wireTimeUs(p.request.bytes.size())));
    } else {
        m_state = State::AwaitingReply;
        m_deadlineUs = m_sentAtUs + qint64(effectiveTimeoutMs(p.request)) * 1000;
        armResponseTimer();
    }
}

void SerialLink::armResponseTimer()
{
    const qint64 firstByte = m_current ? m_current->request.firstByteTimeoutUs : 0;
    qint64 until = m_deadlineUs;
    if (firstByte > 0 && !m_bytesSinceSend)
        until = std::min(until, m_sentAtUs + firstByte);
    m_responseTimer.start(until - nowUs());
}

int SerialLink::effectiveTimeoutMs(const SerialRequest &r) const
{
    if (r.timeoutMs >= 0)
        return r.timeoutMs;
    const int replyBytes = r.expectedReplyBytes > 0 ? r.expectedReplyBytes : kDefaultReplyBytes;
    const qint64 wire = wireTimeUs(r.bytes.size()) + wireTimeUs(replyBytes);
    return static_cast<int>((wire + 999) / 1000) + m_settings.responseTimeoutMs;
}

void SerialLink::onReadyRead()
{
    if (!m_port || m_readingAside)
        return;
    onBytes(m_port->readAll());
}

void SerialLink::readWaitingBytes()
{
    // Through the port, at once, into its buffer (onReadyRead() leaves them there for the
    // caller). Only when bytes wait: with none, waitForReadyRead(0) would report a timeout.
    // A port that fails here reports it as anywhere else (onPortError()).
    if (!bytesWaitInDriver())
        return;
    m_readingAside = true;
    m_port->waitForReadyRead(0);
    m_readingAside = false;
}

bool SerialLink::bytesWaitInDriver() const
{
    // QSerialPort reads only when its notifier fires; reading the descriptor behind its back
    // would make that read fail (EAGAIN), which it reports as a port error.
#ifdef Q_OS_UNIX
    int n = 0;
    return m_port && m_port->handle() >= 0 && ::ioctl(m_port->handle(), FIONREAD, &n) == 0 && n > 0;
#else
    return false;
#endif
}

void SerialLink::onBytes(const QByteArray &data)
{
    if (data.isEmpty())
        return;
    const qint64 now = nowUs();
    m_lastRxUs = now;
    if (m_state != State::AwaitingReply) {
        m_lastReplyPeer = -1; // these bytes are now the last thing on the line
        if (m_tap)
            m_tap->recordSerial(TrafficRecord::Direction::Discarded, m_settings.portName, data,
                                QStringLiteral("unsolicited or late bytes"));
        if (m_recoveryQuietUs > 0)
            m_quietUntilUs = std::max(m_quietUntilUs, now + m_recoveryQuietUs);
        if (m_current && m_state == State::Gap) {
            m_lateForCurrent = true;                // after a timeout of the current request: its late answer,
            m_owed.remove(m_current->request.peer); // which is no longer owed
        }
        payDebtsOf(data);  // a late answer landing while nothing waits pays its peer's debt
        reportStray(data); // (the silence before the next request counts from this byte: m_lastRxUs)
        return;
    }
    if (!m_bytesSinceSend) {
        m_bytesSinceSend = true;
        if (m_current && m_current->request.firstByteTimeoutUs > 0)
            armResponseTimer(); // the whole timeout applies now
    }
    m_rx += data;
    if (m_rx.size() > kMaxRxBuffer)
        discardBuffer(QStringLiteral("receive buffer overflow"));
    processBuffer();
}

void SerialLink::processBuffer()
{
    while (m_current && m_state == State::AwaitingReply && !m_rx.isEmpty()) {
        const FrameMatch m = m_current->request.matcher(m_rx);
        const qsizetype consumed = std::clamp<qsizetype>(m.consumed, 1, m_rx.size());
        switch (m.status) {
        case FrameMatch::Status::Incomplete: return;
        case FrameMatch::Status::Garbage: {
            const QByteArray dropped = m_rx.left(consumed);
            if (m_tap)
                m_tap->recordSerial(TrafficRecord::Direction::Discarded, m_settings.portName, dropped,
                                    QStringLiteral("not the awaited reply"));
            m_rx.remove(0, consumed);
            payDebtsOf(dropped);
            reportStray(dropped);
            continue;
        }
        case FrameMatch::Status::Unfit: {
            anchorSpacingAtReply(consumed); // the drive had the command: it answered
            if (m_tap)
                m_tap->recordSerial(TrafficRecord::Direction::Discarded, m_settings.portName, m_rx.left(consumed),
                                    QStringLiteral("reply does not fit the request"));
            m_rx.remove(0, consumed);
            m_responseTimer.stop();
            const qint64 quiet = std::max<qint64>(m_interFrameGapUs, wireTimeUs(4));
            retryOrFail({ErrorCode::Malformed, m.reason}, quiet);
            return;
        }
        case FrameMatch::Status::Corrupt: {
            ++m_checksumErrors;
            anchorSpacingAtReply(consumed); // the drive had the command: it answered, damaged
            if (m_tap)
                m_tap->recordSerial(TrafficRecord::Direction::Discarded, m_settings.portName, m_rx.left(consumed),
                                    QStringLiteral("bad checksum"));
            m_rx.remove(0, consumed);
            m_responseTimer.stop();
            // The rest of the damaged frame passes before the retry.
            const qint64 quiet = m_interFrameGapUs > 0 ? std::max<qint64>(m_interFrameGapUs, wireTimeUs(8))
                                                       : std::max<qint64>(5000, wireTimeUs(8) + 2000);
            const QString why = !m_current->request.describeCorrupt.isEmpty()
                ? m_current->request.describeCorrupt
                : tr("The drive's reply on %1 failed its checksum. Check the cable "
                     "shielding, the bus termination and the baud rate.")
                      .arg(m_settings.portName);
            retryOrFail({ErrorCode::ChecksumError, why}, quiet);
            return;
        }
        case FrameMatch::Status::Match: {
            const qint64 now = nowUs();
            const qint64 need = (wireTimeUs(m_current->request.bytes.size()) + wireTimeUs(consumed)) / 2;
            const bool early = now - m_sentAtUs < need;
            const int peer = m_current->request.peer;
            // The stale-reply rule (docs/reliability.md): a fast frame is a stale answer only
            // when one could be on its way. Dropping it pays that debt.
            if (early && (m_owed.contains(peer) || m_flushedForCurrent)) {
                ++m_staleReplies;
                m_owed.remove(peer);
                m_flushedForCurrent = false;
                m_current->droppedEarly = true;
                m_lastEarlyUs = now - m_sentAtUs;
                m_lastEarlyNeedUs = 2 * need;
                if (m_tap)
                    m_tap->recordSerial(
                        TrafficRecord::Direction::Discarded, m_settings.portName, m_rx.left(consumed),
                        QStringLiteral("stale: came %1 us after the request (the wire needs %2 us) while an "
                                       "earlier answer was still owed")
                            .arg(m_lastEarlyUs)
                            .arg(m_lastEarlyNeedUs));
                m_rx.remove(0, consumed);
                continue;
            }
            // A peer answers in order: once it answered this request, no earlier answer can follow.
            m_owed.remove(peer);
            if (m_tap)
                m_tap->recordSerial(TrafficRecord::Direction::Rx, m_settings.portName, m.frame);
            m_rx.remove(0, consumed);
            m_lastReplyPeer = m_rx.isEmpty() ? peer : -1; // the last thing on the line, or not
            if (!m_rx.isEmpty()) {
                reportStray(m_rx);
                discardBuffer(QStringLiteral("bytes after the reply"));
            }
            finishCurrent(Error::none(), m.frame);
            return;
        }
        }
    }
}

void SerialLink::onResponseTimeout()
{
    if (!m_current)
        return;
    if (m_state == State::AwaitingWrite) {
        finishCurrent(Error::none());
        return;
    }
    if (m_state != State::AwaitingReply)
        return;
    if (bytesWaitInDriver() && m_deferrals < MaxDeferrals) {
        // The timer came before the port's notifier: what arrived in time counts.
        ++m_deferrals;
        m_responseTimer.start(DeferralUs);
        return;
    }
    m_deferrals = 0;
    if (nowUs() < m_deadlineUs && m_bytesSinceSend) {
        armResponseTimer(); // the first byte came: the whole timeout applies
        return;
    }
    ++m_timeouts;
    if (m_shortGapForCurrent && !m_samePeerGapDropped) {
        // A drive that takes the shorter silence for part of one frame (it hears its own
        // reply, or times frames with the spec's fixed 1.75 ms) ignores such a request.
        m_samePeerGapDropped = true;
        m_gapNote = QStringLiteral("no answer after %1 us of silence: the full %2 us from now on")
                        .arg(m_samePeerGapUs)
                        .arg(m_interFrameGapUs);
        qCInfo(lcSerialLink) << m_settings.portName << m_gapNote;
    }
    const QByteArray unmatched = m_rx;
    if (!m_rx.isEmpty()) {
        reportStray(m_rx);
        discardBuffer(QStringLiteral("incomplete reply at timeout"));
    }
    const int timeout = effectiveTimeoutMs(m_current->request);
    // Unanswered: its answer may still come, and could pass for the next one's. Not when a
    // frame of its shape was dropped as stale: that may have been its answer.
    if (!m_current->droppedEarly)
        m_owed.insert(m_current->request.peer);
    Error e{ErrorCode::Timeout,
            m_current->request.describeTimeout
                ? m_current->request.describeTimeout(timeout, unmatched)
                : tr("No reply on %1 within %2 ms. Check the drive address, the baud rate, the "
                     "wiring (A/B swapped?) and the bus termination.")
                      .arg(m_settings.portName)
                      .arg(timeout)};
    if (m_current->droppedEarly)
        e.message = tr("No reply on %1 within %2 ms but a frame of the awaited shape that came %3 us after "
                       "the request, sooner than the wire can carry request and reply (%4 us), while an "
                       "earlier request was still unanswered: it was dropped as that request's late "
                       "answer. The next attempt accepts a fast reply; if this one was the last, raise the "
                       "retries (--retries).")
                        .arg(m_settings.portName)
                        .arg(timeout)
                        .arg(m_lastEarlyUs)
                        .arg(m_lastEarlyNeedUs);
    // Keep the line quiet long enough that a late reply lands while nothing waits.
    const qint64 quiet = m_current->request.quietAfterTimeoutUs >= 0 ? m_current->request.quietAfterTimeoutUs
                                                                     : qint64(std::max(2 * timeout, 20)) * 1000;
    retryOrFail(e, quiet);
}

void SerialLink::retryOrFail(const Error &error, qint64 quietUs)
{
    enterRecovery(quietUs);
    const int retries = m_current->request.retries >= 0 ? m_current->request.retries : m_settings.retries;
    if (m_current->attempts <= retries && m_current->reply) {
        ++m_retryCount;
        m_state = State::Gap;
        scheduleNext();
        return;
    }
    if (error.code == ErrorCode::Timeout && m_current->sentOnBusyLine) {
        Error e = error;
        e.message += QLatin1Char(' ')
            + tr("The line was never quiet: bytes that answered nothing kept coming, and the request "
                 "was sent into them. Is another master on the bus, or a drive sending on its own? "
                 "Stop the other sender; a longer timeout will not help.");
        finishCurrent(e);
        return;
    }
    if (error.code == ErrorCode::Timeout && m_lateForCurrent) {
        Error e = error;
        e.message += QLatin1Char(' ')
            + tr("Answers came after the timeout: the drive is slower than the response "
                 "allowance (%1 ms): raise the timeout.")
                  .arg(m_settings.responseTimeoutMs);
        finishCurrent(e);
        return;
    }
    finishCurrent(error);
}

void SerialLink::enterRecovery(qint64 quietUs)
{
    const qint64 now = nowUs();
    m_recoveryQuietUs = quietUs;
    // A retry is a command like any other: the minimum gap applies to it too.
    m_quietUntilUs = std::max(m_quietUntilUs, now + std::max(quietUs, qint64(m_settings.minGapMs) * 1000));
}

void SerialLink::finishCurrent(const Error &error, const QByteArray &frame)
{
    m_responseTimer.stop();
    if (!m_current)
        return;
    Pending p = std::move(*m_current);
    m_current.reset();
    const qint64 now = nowUs();
    if (p.reply) {
        p.reply->setAttempts(p.attempts);
        p.reply->setRoundTripUs(now - m_sentAtUs);
        if (error.isError())
            p.reply->finishWithError(error);
        else if (p.request.matcher)
            p.reply->finishWithFrame(frame);
        else
            p.reply->finishEmpty();
    }
    // The reply began after the drive had the whole command: anchoring the command spacing
    // at the reply's first byte (as we saw it, never earlier than it was) keeps it safe from
    // send-side jitter (a USB adapter holding our bytes back) that the estimate from the
    // write cannot see. Nothing may be taken off it: subtracting the quickest turnaround seen
    // (tried in session 9) put commands too close whenever the drive answered faster than
    // it had so far and the adapter held a command back
    // (tst_seriallink heldBackCommandAfterSlowAnswersStillGetsItsSpacing).
    if (!error.isError() && !frame.isEmpty())
        anchorSpacingAtReply(frame.size());
    m_quietUntilUs = std::max(m_quietUntilUs,
                              now + std::max(qint64(m_settings.minGapMs) * 1000, p.request.quietAfterUs));
    m_state = State::Idle;
    scheduleNext();
}

void SerialLink::anchorSpacingAtReply(qsizetype replyBytes)
{
    // The reply began after the drive had the whole command, good or damaged (see finishCurrent()).
    m_lastCommandEndUs = std::max(m_lastCommandEndUs, nowUs() - wireTimeUs(replyBytes));
}

void SerialLink::reportStray(const QByteArray &bytes)
{
    if (bytes.isEmpty())
        return;
    // From the event loop: a receiver may send the next request.
    QMetaObject::invokeMethod(
        this, [this, bytes] { emit strayBytes(bytes); }, Qt::QueuedConnection);
}

bool SerialLink::endsInPartialFrame(const SerialRequest &request, QByteArray bytes)
{
    if (!request.matcher)
        return false;
    while (!bytes.isEmpty()) {
        const FrameMatch m = request.matcher(bytes);
        if (m.status == FrameMatch::Status::Incomplete)
            return true;
        bytes.remove(0, std::clamp<qsizetype>(m.consumed, 1, bytes.size()));
    }
    return false;
}

void SerialLink::payDebtsOf(const QByteArray &strayBytes)
{
    if (!m_strayPeers || m_owed.isEmpty())
        return;
    for (int peer : m_strayPeers(strayBytes))
        m_owed.remove(peer);
}

void SerialLink::discardBuffer(const QString &why)
{
    if (m_tap && !m_rx.isEmpty())
        m_tap->recordSerial(TrafficRecord::Direction::Discarded, m_settings.portName, m_rx, why);
    m_rx.clear();
}

void SerialLink::onPortError(QSerialPort::SerialPortError error)
{
    switch (error) {
    case QSerialPort::ResourceError:
    case QSerialPort::DeviceNotFoundError:
    case QSerialPort::PermissionError:
    case QSerialPort::ReadError:
    case QSerialPort::WriteError: {
        const Error e{ErrorCode::LinkClosed,
                      tr("The serial port %1 failed (%2). Was the adapter unplugged?")
                          .arg(m_settings.portName, m_port ? m_port->errorString() : QString())};
        qCWarning(lcSerialLink) << e.message;
        failAll(e);
        if (m_port) {
            m_port->disconnect(this);
            m_port->close();
            m_port->deleteLater();
            m_port = nullptr;
        }
        emit closed(e);
        break;
    }
    default:
        if (error != QSerialPort::NoError)
            qCDebug(lcSerialLink) << "serial port note:" << error;
        break;
    }
}

} // namespace dd
