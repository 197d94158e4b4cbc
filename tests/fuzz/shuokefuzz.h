#pragma once

// Checks shared by the Shuoke fuzz targets.

#include "tests/fuzz/fuzzsupport.h"

#include "core/protocol/shuoke/shuokeascii.h"
#include "core/protocol/shuoke/shuokecommands.h"
#include "core/protocol/shuoke/shuokeframe.h"
#include "core/protocol/shuoke/shuokertu.h"
#include "core/protocol/shuoke/shuokevalues.h"

#include <cctype>

namespace dd::fuzz {

// The RTU receive options of a control byte: bit0 acceptLengthWithCrc, bit1
// acceptFixedLength, bit2 skipHandshakeCrc.
inline shuoke::RtuOptions rtuOptions(quint8 control)
{
    shuoke::RtuOptions options;
    options.acceptLengthWithCrc = control & 1;
    options.acceptFixedLength = control & 2;
    options.skipHandshakeCrc = control & 4;
    return options;
}

// The ASCII options of a control byte: bit0 check = two's complement, bit1
// acceptLengthPlusOne.
inline shuoke::AsciiOptions asciiOptions(quint8 control)
{
    shuoke::AsciiOptions options;
    options.check = (control & 1) ? shuoke::AsciiCheck::TwosComplement : shuoke::AsciiCheck::PlainSum;
    options.acceptLengthPlusOne = control & 2;
    return options;
}

// An ASCII line with its check byte (the two hex digits before the terminator) recomputed,
// when everything between ':' and them is hex; otherwise the line as it is.
inline QByteArray withRepairedAsciiCheck(const QByteArray &line, shuoke::AsciiCheck check)
{
    qsizetype end = line.size();
    if (line.endsWith("\r\n"))
        end -= 2;
    else if (line.endsWith('\n'))
        end -= 1;
    else
        return line;
    if (!line.startsWith(':') || end < 3 || (end - 3) % 2 != 0)
        return line;
    const QByteArray digits = line.mid(1, end - 3);
    for (const char c : digits) {
        if (!std::isxdigit(static_cast<unsigned char>(c)))
            return line;
    }
    const quint8 sum = shuoke::asciiCheckByte(QByteArray::fromHex(digits), check);
    QByteArray out = line;
    out.replace(end - 2, 2, QByteArray(1, static_cast<char>(sum)).toHex().toUpper());
    return out;
}

// A character stream built from segments [h][h & 0x7F bytes]: with bit 7 of h set the segment
// becomes a line ':' + hex(bytes + check byte) + CR LF, else it is copied as it is.
inline QByteArray asciiSegments(FuzzInput &in, shuoke::AsciiCheck check)
{
    QByteArray out;
    while (in.remaining() > 0) {
        const quint8 h = in.byte();
        const QByteArray segment = in.take(h & 0x7F);
        if (h & 0x80) {
            const QByteArray bytes = segment + QByteArray(1, static_cast<char>(shuoke::asciiCheckByte(segment, check)));
            out += ':' + bytes.toHex().toUpper() + "\r\n";
        } else {
            out += segment;
        }
    }
    return out;
}

// The value codecs a drive's data bytes meet after framing: they must not crash on any
// data, and what they decode re-encodes to something that decodes the same.
inline void checkShuokeValues(const shuoke::Frame &f)
{
    using namespace dd::shuoke;
    DD_FUZZ_CHECK(!(f.failure && !f.data.isEmpty()));
    DD_FUZZ_CHECK(!commandName(f.command).isEmpty());
    if (f.failure) {
        DD_FUZZ_CHECK(!failureDescription(f.failureCode).isEmpty());
        return;
    }
    for (ByteOrder order : {ByteOrder::LittleEndian, ByteOrder::BigEndian}) {
        if (const auto v = decodeUInt32(f.data, order))
            DD_FUZZ_CHECK(encodeUInt32(*v, order) == f.data);
        if (const auto v = decodeInt32(f.data, order))
            DD_FUZZ_CHECK(encodeInt32(*v, order) == f.data);
        if (const auto v = decodeUInt16(f.data, order))
            DD_FUZZ_CHECK(encodeUInt16(*v, order) == f.data);
        if (const auto v = decodeDirection24(f.data, order)) {
            const std::optional<QByteArray> again = encodeDirection24(*v, order);
            DD_FUZZ_CHECK(again && decodeDirection24(*again, order) == v);
        }
        (void)validateRequestData(f.command, f.data, order);
    }
    if (const auto s = decodeMotionStatus(f.data))
        DD_FUZZ_CHECK(decodeMotionStatus(encodeMotionStatus(*s)) == s);
    (void)decodeInputBits(f.data);
    (void)acceptedReplyCommands(f);
    (void)isReplyTo(f, f);
}

} // namespace dd::fuzz
