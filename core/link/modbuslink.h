#pragma once

#include "core/common/error.h"
#include "core/link/linkreply.h"
#include "core/link/serialsettings.h"
#include "core/protocol/modbus/modbusrtu.h"

#include <QObject>

namespace dd {

class TrafficTap;

// One Modbus request for ModbusLink::send().
struct ModbusRequest
{
    modbusrtu::Request pdu; // address, function (0x03 / 0x06 / 0x10), start, count, values
    int timeoutMs = -1;     // -1: wire time of request + reply + settings.responseTimeoutMs
    int retries = -1;       // -1: settings.retries
    QString note;           // shown in the trace
    bool urgent = false;    // stop / disable: ahead of every waiting ordinary request
};

// Modbus RTU client transport on QModbusRtuSerialClient (servo-modbus, shuoke PLC mode),
// with the Qt 6.4 pitfalls of docs/qt-notes.md handled:
//  - requests go one at a time through our own queue; the client's own retries are off;
//  - after a timeout the address is kept quiet (see below) so that a late reply can never
//    be handed to the next request with the same address and function;
//  - setInterFrameDelay(-1) before every connectDevice() (baud changes reconnect);
//  - the response timeout covers the request's and the reply's byte time at the baud;
//  - a serial error (adapter unplugged) closes the link and fails everything pending.
// An urgent request (stop, disable) goes ahead of every waiting ordinary request, behind
// the urgent ones queued before it, right after the request in flight (never aborted; its
// retries come first). The quiet times below apply to it as to any request.
// Exceptions finish the reply with ErrorCode::DriveException and Error::driveCode set.
// The tap receives the request and reply ADUs (rebuilt from the PDUs; CRC included).
//
// Details (measured with Qt 6.4.2, see modbuslink.cpp):
//  - Qt matches a reply by address and function only. The late-reply guard: after a
//    timeout the address is "tainted" for max(2 x timeout, 20 ms), extended while stray
//    bytes arrive; a request to a tainted address (or to address 1, where exception replies
//    with the seed's fixed address byte would land) waits until it is clean. A reply that
//    completes sooner than half the wire time of request + reply after the request went out
//    is discarded as a late answer and the request is repeated after a quiet period.
//  - Qt's shortest response timeout is 10 ms; shorter timeouts (scans at high baud) and
//    aborts (see below) end Qt's wait by disconnecting and reconnecting the client (when a
//    reconnect, whose cost is measured, is quicker than Qt's own timer).
//  - Qt drops a CRC-valid reply whose address byte differs (the servo-modbus exception
//    reply carries 0x01 whatever the drive's address). The raw bytes are seen through a
//    SerialReadSniffer (Unix): such an exception is reported with its code at once and the
//    client is reconnected to end Qt's wait. Without the sniffer the request times out and
//    the error says that a frame from another address arrived.
//  - Qt waits its inter-frame delay (at least 2 ms; 5 ms at 9600 baud) before each request.
class ModbusLink : public QObject
{
    Q_OBJECT
public:
    explicit ModbusLink(QObject *parent = nullptr);
    ~ModbusLink() override;

    void setTap(TrafficTap *tap);
    TrafficTap *tap() const;
    bool open(const SerialSettings &settings, Error *error = nullptr);
    void close();
    bool isOpen() const;
    const SerialSettings &settings() const;
    QString name() const;
    bool setBaudRate(qint32 baud); // between transactions only
    void setResponseTimeoutMs(int ms);
    void setRetries(int retries);
    // An exception reply with this code takes one of the request's retries instead of ending
    // it (servo-modbus: 0x04, also the answer to a damaged request); -1 (default): none.
    void setRetriedExceptionCode(int code);
    void setMinGapMs(int ms);
    void setMinCommandSpacingMs(int ms);

    // Replies carry registers(): the values read, or for writes the echoed start/count
    // (0x10) or register/value (0x06).
    LinkReply *readHoldingRegisters(int serverAddress, int start, int count, int timeoutMs = -1);
    LinkReply *writeRegisters(int serverAddress, int start, const QList<quint16> &values, int timeoutMs = -1);
    LinkReply *writeSingleRegister(int serverAddress, int reg, quint16 value, int timeoutMs = -1);
    LinkReply *send(const ModbusRequest &request);
    void cancelAll(const Error &why);

    bool isIdle() const;
    int queuedCount() const;
    quint64 timeoutCount() const;
    quint64 retryCount() const;
    quint64 checksumErrorCount() const;
    quint64 lateReplyCount() const; // replies discarded as late answers
    quint64 reconnectCount() const; // client reconnects (short timeouts, aborts)
    bool seesRawBytes() const;      // the SerialReadSniffer works on this platform

    // Wire time of `bytes` characters at the current settings, in microseconds.
    qint64 wireTimeUs(qsizetype bytes) const;
    // The response timeout a request gets when it does not set one.
    int defaultTimeoutMs(const modbusrtu::Request &pdu) const;
    // Qt's inter-frame delay before each request at the current baud, in microseconds.
    int interFrameDelayUs() const;

signals:
    void opened();
    void closed(const dd::Error &reason);
    void idle();
    // Raw bytes no request took (Unix, where the raw bytes are visible): bytes that arrived
    // with no request waiting (also those still unread at the port when a request goes
    // out, which the link then flushes), bytes that formed no reply before a timeout, a
    // CRC-valid frame from another address. May come before the timeout of the request
    // whose late answer they are. Typically a late reply to an earlier request; the
    // scanner uses them to ask such an address again. Emitted from the event loop.
    void strayBytes(const QByteArray &bytes);

private:
    class Private;
    Private *d;
};

} // namespace dd
