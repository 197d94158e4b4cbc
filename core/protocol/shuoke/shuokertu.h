#pragma once

#include "core/protocol/codecresult.h"
#include "core/protocol/shuoke/shuokeframe.h"

#include <QByteArray>
#include <QList>

// Shuoke serial RTU framing: [addr][cmd][len][data x len][crc lo][crc hi], CRC-16/MODBUS
// over addr..data, low byte first.
//
// Receive tolerance (docs/protocols/shuoke.md decisions and seed 0x49):
// - Standard: len = number of data bytes (every worked example of the seed);
// - LengthCountsCrc: len also counts the two CRC bytes (the seed's prose), accepted when
//   the CRC checks and the command carries that many data bytes somewhere in the table;
// - FixedLength: the M4505S "fixed 8-byte replies" setting (0x49): 10 bytes on the wire
//   whatever len says, data zero-padded to 5 bytes; len = the meaningful data bytes.
// When several readings check, Standard wins over LengthCountsCrc over FixedLength.
namespace dd::shuoke {

enum class RtuLayout : quint8 { Standard, LengthCountsCrc, FixedLength };

struct RtuOptions
{
    bool acceptLengthWithCrc = true; // receive: also LengthCountsCrc
    bool acceptFixedLength = true;   // receive: also FixedLength
    bool padToFixedLength = false;   // send: FixedLength layout (frames with <= 5 data bytes)
    bool skipHandshakeCrc = false;   // receive, drive side: 0x20 is taken without a CRC check
};

constexpr int kRtuOverhead = 5; // addr, cmd, len, crc lo, crc hi
constexpr int kRtuMinFrameSize = 5;
constexpr int kFixedFrameSize = 10; // FixedLength layout
constexpr int kFixedDataSize = 5;

// The wire bytes of `frame`. Fails when the data has more than 255 bytes.
Decoded<QByteArray> encodeRtu(const Frame &frame, const RtuOptions &options = {});

// Decodes exactly one complete frame (no bytes before or after it). `layout`, when given,
// receives the layout that matched.
Decoded<Frame> decodeRtu(const QByteArray &bytes, const RtuOptions &options = {}, RtuLayout *layout = nullptr);

namespace detail {
// One reading of a header [addr][cmd][len]: the frame would be `size` bytes long and carry
// `dataLength` data bytes.
struct RtuCandidate
{
    int size = 0;
    int dataLength = 0;
    RtuLayout layout = RtuLayout::Standard;
};
// The readings `options` allow for this command byte and len, in order of preference.
// A failure reply (cmd & 0x80) must carry exactly one data byte.
QList<RtuCandidate> rtuCandidates(quint8 commandByte, quint8 len, const RtuOptions &options);
// Whether the first `c.size` bytes at `p` form the frame `c` describes (CRC, and for the
// non-standard layouts a command/length pair the table knows).
bool rtuCandidateMatches(const char *p, const RtuCandidate &c, const RtuOptions &options);
// The frame the first `c.size` bytes at `p` carry (call after rtuCandidateMatches).
Frame rtuFrameFrom(const char *p, const RtuCandidate &c);
} // namespace detail

} // namespace dd::shuoke
