#pragma once

#include "core/protocol/codecresult.h"
#include "core/protocol/shuoke/shuokeframe.h"

#include <QByteArray>

// Shuoke serial ASCII framing: ':' + two upper-case hex digits for every byte of
// [addr][cmd][len][data][check] + CR LF.
//
// - Check byte: the seed's "sum of all bytes before it, low 8 bits" (':' CR LF excluded)
//   by default; the standard Modbus LRC (two's complement of that sum) as a setting.
// - len: data bytes when sending. The seed says ASCII len is one less than RTU's while its
//   own example uses the same len for both: on receive, len = data + 1 is accepted too
//   (the check byte still has to match).
// - Receive tolerance: lower-case hex digits and a bare LF terminator are accepted.
namespace dd::shuoke {

enum class AsciiCheck : quint8 { PlainSum, TwosComplement };

struct AsciiOptions
{
    AsciiCheck check = AsciiCheck::PlainSum;
    bool acceptLengthPlusOne = true;
};

constexpr char kAsciiStart = ':';

// Check byte over `bytes` (addr..data).
quint8 asciiCheckByte(const QByteArray &bytes, AsciiCheck check = AsciiCheck::PlainSum);

// ":...\r\n". Fails when the data has more than 255 bytes.
Decoded<QByteArray> encodeAscii(const Frame &frame, const AsciiOptions &options = {});

// Decodes exactly one line, from ':' to the terminating LF inclusive.
Decoded<Frame> decodeAscii(const QByteArray &line, const AsciiOptions &options = {});

} // namespace dd::shuoke
