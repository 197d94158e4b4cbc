#pragma once

// Internal to ModbusLink; not part of the core API.

#include "core/link/modbuslink.h"
#include "core/link/serialreadsniffer.h"

#include <QElapsedTimer>
#include <QHash>
#include <QModbusDevice>
#include <QPointer>
#include <QQueue>
#include <QSet>
#include <QTimer>
#include <optional>

class QModbusReply;
class QModbusResponse;
class QModbusRtuSerialClient;

namespace dd {

class ModbusLink::Private : public QObject
{
    Q_OBJECT
public:
    explicit Private(ModbusLink *q);
    ~Private() override;

    struct Pending
    {
        ModbusRequest request;
        QPointer<LinkReply> reply;
        int attempts = 0;
        bool droppedEarly = false; // a fast frame was dropped as a stale answer
    };
    enum class State {
        Idle,    // nothing in flight
        Waiting, // the next request waits for a quiet line / a clean address
        Awaiting // handed to the Qt client, waiting for its reply
    };

    bool open(const SerialSettings &settings, Error *error);
    void close(const Error &why);
    bool isOpen() const;
    bool reconnect(Error *error);
    LinkReply *enqueue(const ModbusRequest &request);
    void failAll(const Error &why, bool abortQt = true);
    void scheduleNext();
    qint64 nowUs() const { return m_clock.nsecsElapsed() / 1000; }
    qint64 wireTimeUs(qsizetype bytes) const;
    int effectiveTimeoutMs(const ModbusRequest &r) const;

    ModbusLink *q;
    SerialSettings m_settings;
    TrafficTap *m_tap = nullptr;
    QModbusRtuSerialClient *m_client = nullptr;
    SerialReadSniffer m_sniffer;
    QQueue<Pending> m_queue;
    std::optional<Pending> m_current;
    State m_state = State::Idle;
    QPointer<QModbusReply> m_qtReply;
    QTimer m_gapTimer;
    QTimer m_abortTimer;
    QElapsedTimer m_clock;

    qint64 m_sentLowerBoundUs = 0; // the request cannot have left before this
    qint64 m_writtenUs = 0;        // Qt handed the current request to the port (0: not yet)
    qint64 m_lastRxUs = 0;         // the last sniffed bytes while awaiting (0: none)
    qint64 m_lastFinishUs = 0;
    qint64 m_lastCommandEndUs = 0; // the last request's last byte left the port (0: none yet)
    qint64 m_quietUntilUs = 0;     // no request before this (stray bytes, broadcast turnaround)
    QByteArray m_rxSinceSend;      // sniffed bytes since the current request went to Qt
    bool m_mismatchSeen = false;   // Qt dropped a CRC-valid frame from another address
    bool m_crcErrorSeen = false;
    bool m_aborting = false;             // we are reconnecting: ignore what Qt reports meanwhile
    QHash<int, qint64> m_taintedUntilUs; // address -> no request before this (late replies)
    QSet<int> m_owed;                    // addresses whose last request went unanswered (the stale-reply rule)

    quint64 m_timeouts = 0;
    quint64 m_retries = 0;
    quint64 m_checksumErrors = 0;
    int m_retriedExceptionCode = -1; // ModbusLink::setRetriedExceptionCode
    quint64 m_lateReplies = 0;
    quint64 m_reconnects = 0;
    qint64 m_reconnectCostUs = 1000; // running average of a client reconnect
    quint64 m_strayBursts = 0;

private:
    void transmit();
    void onQtFinished(QModbusReply *reply);
    void onQtIntermediateError(QModbusReply *reply, QModbusDevice::IntermediateError error);
    void onAbortTimer();
    void onClientError(QModbusDevice::Error error);
    void onSniffed(const QByteArray &bytes);
    void onBytesWritten();
    void reportStray(const QByteArray &bytes);
    void onDeviceReadyRead();
    bool abortInFlight();
    void handleSuccess(const QModbusResponse &response);
    void noteStrayActivity();
    void finishCurrent(const Error &error, const QList<quint16> &registers = {});
    void retryOrFail(const Error &error, int quietMs);
    void finishException(const Error &error); // exception reply: retried code or the end
    void taint(int address, qint64 untilUs);
    qint64 cleanAtUs(int address) const;
    void recordTx(const QByteArray &adu, const QString &note);
    void recordRx(const QByteArray &adu, const QString &note = {});
    void recordDiscarded(const QByteArray &bytes, const QString &note);
    QByteArray exceptionInSniffedBytes() const;
    QByteArray strayFrameInSniffedBytes() const;
    void handleTimeout(int timeoutMs);
    int quietAfterTimeoutMs(int timeoutMs) const;
    int silenceMs() const;
};

} // namespace dd
