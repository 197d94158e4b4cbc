#pragma once

#include "core/common/error.h"
#include "core/link/linkreply.h"
#include "core/link/seriallink.h"
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
    // After a timeout the line stays quiet this long; -1: the link's rule (max(2 x timeout,
    // 20 ms), so that a late reply lands while nothing waits). The scanner, which catches
    // late replies itself (strayBytes), passes interFrameGapUs().
    qint64 quietAfterTimeoutUs = -1;
    // > 0: time out when no byte came this long after the request went out (scan probes:
    // the request's wire time + the allowance), not after the whole reply's wire time.
    qint64 firstByteTimeoutUs = 0;
};

// Modbus RTU client transport (servo-modbus, shuoke PLC mode): the project's SerialLink
// with the RTU codec (modbusrtu::) and the reply matcher of modbusreplymatcher.h.
//  - requests go one at a time (SerialLink's queue, urgent ones first), each after the
//    Modbus inter-frame silence t3.5 (3.5 characters; 1750 us above 19200 baud) counted
//    from the last byte seen on the line, to the microsecond; a request to the drive whose
//    reply was the last thing on the line waits 3.5 characters at every baud, until one
//    such request goes unanswered (sameDriveGapUs());
//  - a reply is the first CRC-valid frame that answers the request: its address and
//    function, or an exception for its function whatever the address byte (the
//    servo-modbus drive sends exception replies with address 0x01). Frames from other
//    addresses or of other functions are passed over (strayBytes, the timeout's words);
//    a frame from the address that does not fit (byte count, echo) is Malformed and the
//    request is asked again; a frame-shaped run with a bad CRC is ChecksumError, again;
//  - the stale-reply rule of docs/reliability.md (SerialLink): a fast reply is dropped as
//    a stale answer only when its address owes one;
//  - a broadcast (address 0) finishes when written; the line then stays quiet 100 ms;
//  - a serial error (adapter unplugged) closes the link and fails everything pending.
// Exceptions finish the reply with ErrorCode::DriveException and Error::driveCode set.
// The tap receives the request and reply ADUs as they were on the wire.
class ModbusLink : public QObject
{
    Q_OBJECT
public:
    static constexpr int BroadcastTurnaroundMs = 100; // Modbus: let servers act on a broadcast

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
    quint64 lateReplyCount() const; // fast replies dropped as stale answers

    // Wire time of `bytes` characters at the current settings, in microseconds.
    qint64 wireTimeUs(qsizetype bytes) const;
    // The response timeout a request gets when it does not set one.
    int defaultTimeoutMs(const modbusrtu::Request &pdu) const;
    // The Modbus inter-frame silence t3.5 at the current baud, in microseconds.
    qint64 interFrameGapUs() const;
    static qint64 interFrameGapUs(qint32 baud, int bitsPerChar);
    // The silence before a request to the drive that has just answered: 3.5 characters
    // (0.3 ms at 115200), until a drive leaves such a request unanswered; then
    // interFrameGapUs() (SerialLink::setSamePeerGapUs).
    qint64 sameDriveGapUs() const;
    static qint64 sameDriveGapUs(qint32 baud, int bitsPerChar);

signals:
    void opened();
    void closed(const dd::Error &reason);
    void idle();
    // Raw bytes no request took: bytes that arrived with no request waiting (also those
    // still unread at the port when a request goes out, which the link then flushes),
    // frames from other addresses or of other functions, bytes that formed no reply before
    // a timeout. Typically a late reply to an earlier request: the scanner asks such an
    // address again. May come before the timeout of the request whose late answer they
    // are. Emitted from the event loop.
    void strayBytes(const QByteArray &bytes);

private:
    // Sends `s` for `outer`, which has already used `attemptsBefore` attempts.
    void transmit(LinkReply *outer, const SerialRequest &s, const modbusrtu::Request &pdu, int attemptsBefore);
    void finishFrom(LinkReply *outer, LinkReply *inner, const SerialRequest &s, const modbusrtu::Request &pdu,
                    int attemptsBefore);

    SerialLink *m_serial;
    int m_retriedExceptionCode = -1; // setRetriedExceptionCode
};

} // namespace dd
