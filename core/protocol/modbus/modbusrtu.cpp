#include "core/protocol/modbus/modbusrtu.h"

#include "core/common/hextext.h"
#include "core/protocol/modbus/crc16.h"

#include <algorithm>

namespace dd::modbusrtu {

namespace {

quint8 byteAt(const QByteArray &a, qsizetype i)
{
    return static_cast<quint8>(a.at(i));
}

quint16 wordAt(const QByteArray &a, qsizetype i)
{
    return static_cast<quint16>((byteAt(a, i) << 8) | byteAt(a, i + 1));
}

void appendWord(QByteArray &out, quint16 v)
{
    out.append(static_cast<char>(v >> 8));
    out.append(static_cast<char>(v & 0xFF));
}

QByteArray header(quint8 address, quint8 function)
{
    QByteArray out;
    out.reserve(MaxAduSize);
    out.append(static_cast<char>(address));
    out.append(static_cast<char>(function));
    return out;
}

// A caller's limit never widens the Modbus one: 124 or 125 registers of 0x10 would not fit
// an ADU (and the encoders refuse them), so "maxCount 125 for both functions" means 123 for 0x10.
int limitFor(quint8 function, int maxCount)
{
    const int standard = function == WriteMultipleRegisters ? StandardMaxWriteCount : StandardMaxReadCount;
    return maxCount > 0 ? std::min(maxCount, standard) : standard;
}

template <typename T>
Decoded<T> fail(DecodeError *reason, DecodeError e, const QString &why)
{
    if (reason)
        *reason = e;
    return Decoded<T>::failure(decodeErrorName(e) + QStringLiteral(": ") + why);
}

template <typename T>
Decoded<T> succeed(DecodeError *reason, T v)
{
    if (reason)
        *reason = DecodeError::None;
    return Decoded<T>::success(std::move(v));
}

} // namespace

QString decodeErrorName(DecodeError e)
{
    switch (e) {
    case DecodeError::None: return QStringLiteral("none");
    case DecodeError::TooShort: return QStringLiteral("too-short");
    case DecodeError::BadCrc: return QStringLiteral("bad-crc");
    case DecodeError::UnknownFunction: return QStringLiteral("unknown-function");
    case DecodeError::WrongLength: return QStringLiteral("wrong-length");
    case DecodeError::ByteCountMismatch: return QStringLiteral("byte-count-mismatch");
    case DecodeError::CountOutOfRange: return QStringLiteral("count-out-of-range");
    case DecodeError::AddressMismatch: return QStringLiteral("address-mismatch");
    case DecodeError::FunctionMismatch: return QStringLiteral("function-mismatch");
    case DecodeError::CountMismatch: return QStringLiteral("count-mismatch");
    case DecodeError::EchoMismatch: return QStringLiteral("echo-mismatch");
    }
    return QStringLiteral("unknown");
}

QString exceptionCodeName(quint8 code)
{
    switch (code) {
    case IllegalFunction: return QStringLiteral("illegal function");
    case IllegalDataAddress: return QStringLiteral("illegal data address");
    case IllegalDataValue: return QStringLiteral("illegal data value");
    case ServerDeviceFailure: return QStringLiteral("server device failure");
    case Acknowledge: return QStringLiteral("acknowledge");
    case ServerDeviceBusy: return QStringLiteral("server device busy");
    case MemoryParityError: return QStringLiteral("memory parity error");
    case GatewayPathUnavailable: return QStringLiteral("gateway path unavailable");
    case GatewayTargetFailedToRespond: return QStringLiteral("gateway target failed to respond");
    default: return QStringLiteral("exception ") + hexText(code, 2);
    }
}

bool isKnownFunction(quint8 function)
{
    return function == ReadHoldingRegisters || function == WriteSingleRegister || function == WriteMultipleRegisters;
}

// ---- Encoders ----

QByteArray encodeReadHoldingRequest(quint8 address, quint16 start, quint16 count)
{
    if (count < 1 || count > StandardMaxReadCount)
        return {};
    QByteArray out = header(address, ReadHoldingRegisters);
    appendWord(out, start);
    appendWord(out, count);
    return withCrc16(out);
}

QByteArray encodeWriteSingleRequest(quint8 address, quint16 reg, quint16 value)
{
    QByteArray out = header(address, WriteSingleRegister);
    appendWord(out, reg);
    appendWord(out, value);
    return withCrc16(out);
}

QByteArray encodeWriteMultipleRequest(quint8 address, quint16 start, const QList<quint16> &values)
{
    if (values.isEmpty() || values.size() > StandardMaxWriteCount)
        return {};
    QByteArray out = header(address, WriteMultipleRegisters);
    appendWord(out, start);
    appendWord(out, static_cast<quint16>(values.size()));
    out.append(static_cast<char>(values.size() * 2));
    for (quint16 v : values)
        appendWord(out, v);
    return withCrc16(out);
}

QByteArray encodeRequest(const Request &request)
{
    switch (request.function) {
    case ReadHoldingRegisters: return encodeReadHoldingRequest(request.address, request.start, request.count);
    case WriteSingleRegister:
        if (request.values.size() != 1)
            return {};
        return encodeWriteSingleRequest(request.address, request.start, request.values.first());
    case WriteMultipleRegisters:
        if (request.values.size() != request.count)
            return {};
        return encodeWriteMultipleRequest(request.address, request.start, request.values);
    default: return {};
    }
}

QByteArray encodeReadHoldingReply(quint8 address, const QList<quint16> &values)
{
    if (values.isEmpty() || values.size() > StandardMaxReadCount)
        return {};
    QByteArray out = header(address, ReadHoldingRegisters);
    out.append(static_cast<char>(values.size() * 2));
    for (quint16 v : values)
        appendWord(out, v);
    return withCrc16(out);
}

QByteArray encodeWriteSingleReply(quint8 address, quint16 reg, quint16 value)
{
    QByteArray out = header(address, WriteSingleRegister);
    appendWord(out, reg);
    appendWord(out, value);
    return withCrc16(out);
}

QByteArray encodeWriteMultipleReply(quint8 address, quint16 start, quint16 count)
{
    QByteArray out = header(address, WriteMultipleRegisters);
    appendWord(out, start);
    appendWord(out, count);
    return withCrc16(out);
}

QByteArray encodeExceptionReply(quint8 address, quint8 function, quint8 code)
{
    QByteArray out = header(address, static_cast<quint8>(function | ExceptionFlag));
    out.append(static_cast<char>(code));
    return withCrc16(out);
}

int expectedReplySize(const Request &request)
{
    switch (request.function) {
    case ReadHoldingRegisters: return 5 + 2 * request.count;
    case WriteSingleRegister:
    case WriteMultipleRegisters: return 8;
    default: return 0;
    }
}

// ---- Decoders ----

Decoded<Request> decodeRequest(const QByteArray &adu, int maxCount, DecodeError *reason)
{
    using R = Request;
    const qsizetype n = adu.size();
    if (n < 4)
        return fail<R>(reason, DecodeError::TooShort, QStringLiteral("%1 bytes").arg(n));
    if (!hasValidCrc16(adu))
        return fail<R>(reason, DecodeError::BadCrc, QStringLiteral("CRC mismatch over %1 bytes").arg(n));

    Request r;
    r.address = byteAt(adu, 0);
    r.function = byteAt(adu, 1);
    if (!isKnownFunction(r.function))
        return fail<R>(reason, DecodeError::UnknownFunction, QStringLiteral("function %1").arg(hexText(r.function, 2)));

    if (r.function == ReadHoldingRegisters || r.function == WriteSingleRegister) {
        if (n != 8)
            return fail<R>(reason, DecodeError::WrongLength,
                           QStringLiteral("function %1 request is 8 bytes, got %2").arg(hexText(r.function, 2)).arg(n));
        r.start = wordAt(adu, 2);
        if (r.function == WriteSingleRegister) {
            r.count = 1;
            r.values = {wordAt(adu, 4)};
            return succeed(reason, r);
        }
        r.count = wordAt(adu, 4);
    } else { // WriteMultipleRegisters
        if (n < 9)
            return fail<R>(reason, DecodeError::WrongLength,
                           QStringLiteral("function 0x10 request is at least 9 bytes, got %1").arg(n));
        r.start = wordAt(adu, 2);
        r.count = wordAt(adu, 4);
        const int byteCount = byteAt(adu, 6);
        if (n != 9 + byteCount)
            return fail<R>(reason, DecodeError::ByteCountMismatch,
                           QStringLiteral("byte count %1 but %2 data bytes").arg(byteCount).arg(n - 9));
        if (byteCount != 2 * r.count)
            return fail<R>(reason, DecodeError::ByteCountMismatch,
                           QStringLiteral("byte count %1 for %2 registers").arg(byteCount).arg(r.count));
        r.values.reserve(r.count);
        for (int i = 0; i < r.count; ++i)
            r.values.append(wordAt(adu, 7 + 2 * i));
    }
    const int limit = limitFor(r.function, maxCount);
    if (r.count < 1 || r.count > limit)
        return fail<R>(reason, DecodeError::CountOutOfRange,
                       QStringLiteral("%1 registers, allowed 1..%2").arg(r.count).arg(limit));
    return succeed(reason, r);
}

Decoded<Reply> decodeReply(const QByteArray &adu, const Request &request, DecodeError *reason)
{
    using R = Reply;
    const qsizetype n = adu.size();
    if (n < ExceptionReplySize)
        return fail<R>(reason, DecodeError::TooShort, QStringLiteral("%1 bytes").arg(n));
    if (!hasValidCrc16(adu))
        return fail<R>(reason, DecodeError::BadCrc, QStringLiteral("CRC mismatch over %1 bytes").arg(n));
    if (request.address == BroadcastAddress)
        return fail<R>(reason, DecodeError::AddressMismatch,
                       QStringLiteral("reply from %1 to a broadcast request").arg(hexText(byteAt(adu, 0), 2)));

    Reply r;
    r.address = byteAt(adu, 0);
    const quint8 fc = byteAt(adu, 1);
    if (fc == (request.function | ExceptionFlag)) {
        // Exception: the address byte is not judged (the servo-modbus drive fixes it to 0x01).
        if (n != ExceptionReplySize)
            return fail<R>(reason, DecodeError::WrongLength,
                           QStringLiteral("exception reply is 5 bytes, got %1").arg(n));
        r.function = request.function;
        r.isException = true;
        r.exceptionCode = byteAt(adu, 2);
        return succeed(reason, r);
    }
    if (fc & ExceptionFlag) // an exception, also not judged by its address, to another function
        return fail<R>(reason, DecodeError::FunctionMismatch,
                       QStringLiteral("exception reply for function %1, request function %2")
                           .arg(hexText(fc & 0x7F, 2), hexText(request.function, 2)));
    if (r.address != request.address)
        return fail<R>(
            reason, DecodeError::AddressMismatch,
            QStringLiteral("reply from %1, request to %2").arg(hexText(r.address, 2), hexText(request.address, 2)));
    if (fc != request.function)
        return fail<R>(
            reason, DecodeError::FunctionMismatch,
            QStringLiteral("reply function %1, request function %2").arg(hexText(fc, 2), hexText(request.function, 2)));
    r.function = fc;

    switch (fc) {
    case ReadHoldingRegisters: {
        const int byteCount = byteAt(adu, 2);
        if (n != 5 + byteCount)
            return fail<R>(reason, DecodeError::ByteCountMismatch,
                           QStringLiteral("byte count %1 but %2 data bytes").arg(byteCount).arg(n - 5));
        if (byteCount % 2 != 0)
            return fail<R>(reason, DecodeError::ByteCountMismatch, QStringLiteral("odd byte count %1").arg(byteCount));
        if (byteCount / 2 != request.count)
            return fail<R>(reason, DecodeError::CountMismatch,
                           QStringLiteral("%1 registers returned, %2 requested").arg(byteCount / 2).arg(request.count));
        r.count = static_cast<quint16>(byteCount / 2);
        r.values.reserve(r.count);
        for (int i = 0; i < r.count; ++i)
            r.values.append(wordAt(adu, 3 + 2 * i));
        return succeed(reason, r);
    }
    case WriteSingleRegister:
    case WriteMultipleRegisters: {
        if (n != 8)
            return fail<R>(reason, DecodeError::WrongLength,
                           QStringLiteral("function %1 reply is 8 bytes, got %2").arg(hexText(fc, 2)).arg(n));
        r.start = wordAt(adu, 2);
        if (r.start != request.start)
            return fail<R>(
                reason, DecodeError::EchoMismatch,
                QStringLiteral("register %1 echoed, %2 sent").arg(hexText(r.start, 4), hexText(request.start, 4)));
        if (fc == WriteSingleRegister) {
            r.count = 1;
            r.values = {wordAt(adu, 4)};
            return succeed(reason, r);
        }
        r.count = wordAt(adu, 4);
        if (r.count != request.count)
            return fail<R>(reason, DecodeError::EchoMismatch,
                           QStringLiteral("count %1 echoed, %2 sent").arg(r.count).arg(request.count));
        return succeed(reason, r);
    }
    default: return fail<R>(reason, DecodeError::UnknownFunction, QStringLiteral("function %1").arg(hexText(fc, 2)));
    }
}

} // namespace dd::modbusrtu
