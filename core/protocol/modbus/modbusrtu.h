#pragma once

#include "core/protocol/codecresult.h"

#include <QByteArray>
#include <QList>
#include <QString>
#include <QtGlobal>

// Modbus RTU codec for the three function codes the drives of this project use:
// 0x03 read holding registers, 0x06 write single register, 0x10 write multiple registers.
// Pure functions over complete ADUs ([address][PDU][CRC low][CRC high]); registers are
// big-endian on the wire as Modbus specifies. No I/O, no state.
namespace dd::modbusrtu {

enum FunctionCode : quint8 { ReadHoldingRegisters = 0x03, WriteSingleRegister = 0x06, WriteMultipleRegisters = 0x10 };

constexpr quint8 ExceptionFlag = 0x80;     // set in the function byte of an exception reply
constexpr quint8 BroadcastAddress = 0x00;  // never answered
constexpr int MaxAduSize = 256;            // Modbus RTU limit, CRC included
constexpr int ExceptionReplySize = 5;      // [addr][fc|0x80][code][crc lo][crc hi]
constexpr int StandardMaxReadCount = 125;  // Modbus limit for 0x03
constexpr int StandardMaxWriteCount = 123; // Modbus limit for 0x10
// Pass as `maxCount` to use the Modbus limit of the function (125 for 0x03, 123 for 0x10).
constexpr int UseStandardLimit = 0;

// Modbus exception codes (the servo-modbus drive always uses 0x04).
enum ExceptionCode : quint8 {
    IllegalFunction = 0x01,
    IllegalDataAddress = 0x02,
    IllegalDataValue = 0x03,
    ServerDeviceFailure = 0x04,
    Acknowledge = 0x05,
    ServerDeviceBusy = 0x06,
    MemoryParityError = 0x08,
    GatewayPathUnavailable = 0x0A,
    GatewayTargetFailedToRespond = 0x0B
};

// Why a decoder rejected an ADU. The Decoded<T>::error string says the same in words,
// with the offending numbers.
enum class DecodeError {
    None = 0,
    TooShort,          // fewer bytes than the smallest frame of that kind
    BadCrc,            // CRC over the frame does not match its last two bytes
    UnknownFunction,   // function code not 0x03 / 0x06 / 0x10 (or their exceptions)
    WrongLength,       // frame length does not fit its function code
    ByteCountMismatch, // byte-count field disagrees with the frame length or register count
    CountOutOfRange,   // register count 0 or above the limit
    AddressMismatch,   // reply from another address (never for exception replies)
    FunctionMismatch,  // reply to another function code
    CountMismatch,     // 0x03 reply carries a different number of registers than requested
    EchoMismatch       // 0x06 / 0x10 reply does not echo the request's register / count
};

QString decodeErrorName(DecodeError e); // stable English identifier, e.g. "bad-crc"
QString exceptionCodeName(quint8 code); // e.g. "server device failure", or "exception 0x42"
bool isKnownFunction(quint8 function);  // 0x03, 0x06 or 0x10

// A request as the drive sees it.
//  0x03: start, count; values empty.
//  0x06: start = register, count = 1, values = {value}.
//  0x10: start, count, values (count of them).
struct Request
{
    quint8 address = 0;
    quint8 function = 0;
    quint16 start = 0;
    quint16 count = 0;
    QList<quint16> values;

    bool operator==(const Request &o) const
    {
        return address == o.address && function == o.function && start == o.start && count == o.count
            && values == o.values;
    }
    bool operator!=(const Request &o) const { return !(*this == o); }
};

// A reply as the host sees it.
//  exception: isException, function = the request's function (flag removed), exceptionCode.
//  0x03: values = the registers read, count = values.size().
//  0x06: start = register, count = 1, values = {value as the drive returned it}.
//  0x10: start, count as echoed; values empty.
struct Reply
{
    quint8 address = 0;
    quint8 function = 0;
    bool isException = false;
    quint8 exceptionCode = 0;
    quint16 start = 0;
    quint16 count = 0;
    QList<quint16> values;

    bool operator==(const Reply &o) const
    {
        return address == o.address && function == o.function && isException == o.isException
            && exceptionCode == o.exceptionCode && start == o.start && count == o.count && values == o.values;
    }
    bool operator!=(const Reply &o) const { return !(*this == o); }
};

// ---- Encoders: complete ADUs with CRC (low byte first). ----
// They refuse (return an empty QByteArray) what Modbus does not allow: 0x03 count outside
// 1..125, 0x10 with 0 or more than 123 values, a 0x03 reply with 0 or more than 125 values.
QByteArray encodeReadHoldingRequest(quint8 address, quint16 start, quint16 count);
QByteArray encodeWriteSingleRequest(quint8 address, quint16 reg, quint16 value);
QByteArray encodeWriteMultipleRequest(quint8 address, quint16 start, const QList<quint16> &values);
QByteArray encodeRequest(const Request &request); // by request.function; empty if unknown

QByteArray encodeReadHoldingReply(quint8 address, const QList<quint16> &values);
QByteArray encodeWriteSingleReply(quint8 address, quint16 reg, quint16 value);
QByteArray encodeWriteMultipleReply(quint8 address, quint16 start, quint16 count);
QByteArray encodeExceptionReply(quint8 address, quint8 function, quint8 code);

// Length in bytes of the normal (non-exception) reply to `request`; 0 for an unknown function.
int expectedReplySize(const Request &request);

// ---- Decoders ----
// Drive side: one complete request ADU. `maxCount` is the register limit of 0x03 / 0x10
// (UseStandardLimit = Modbus limits; servo-modbus passes 20). The address is not judged:
// the caller decides whether the request is for it (or a broadcast).
// Checks, in order: size >= 4, CRC, function code, length for the function, 0x10 byte
// count (against the frame and against 2 * count), count in 1..maxCount. A maxCount above
// the Modbus limit of the function is lowered to it.
// `reason`, when given, receives the DecodeError (None on success).
Decoded<Request> decodeRequest(const QByteArray &adu, int maxCount = UseStandardLimit, DecodeError *reason = nullptr);

// Host side: one complete reply ADU, judged against the request it answers.
// Checks, in order: size >= 5, CRC, then
//  - function byte == request.function | 0x80: an exception reply, accepted WHATEVER its
//    address byte (the servo-modbus drive fixes it to 0x01); must be exactly 5 bytes;
//  - an exception reply for another function is FunctionMismatch, whatever its address;
//  - otherwise address == request.address, function == request.function, length and
//    byte count, register count (0x03), echo of register / start / count (0x06, 0x10).
// The value of a 0x06 reply is returned, not compared with the request's: the
// servo-modbus legacy EE operation reports progress in it (0 = still running).
// A request to the broadcast address expects no reply: any reply is AddressMismatch.
Decoded<Reply> decodeReply(const QByteArray &adu, const Request &request, DecodeError *reason = nullptr);

} // namespace dd::modbusrtu
