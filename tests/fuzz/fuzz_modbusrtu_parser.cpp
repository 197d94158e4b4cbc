// ModbusRtuStreamParser, both modes (core/protocol/modbusrtuparser.h), and its static
// checkFrame() used by the serial link's reply matcher.
// Input: [mode/cap: bit0 = Replies, bits 1..7 = cap selector (0 = default 256, else 8 + n)]
//        [chunk: feed() slices of 1 + chunk bytes][format: bit0 = segments]
//        [byte stream, or with bit0 segments that become frames with a CRC or noise: see
//        fuzz::segmentsWithCrc()].
// Invariants: fewer than bufferCap bytes wait after every feed(); every delivered frame is
// CRC-valid, at most bufferCap long, a frame by checkFrame() and present in the input; no byte
// is lost or invented (discarded + delivered + pending == fed); discardPending() empties.

#include "tests/fuzz/fuzzsupport.h"

#include "core/protocol/modbus/crc16.h"
#include "core/protocol/modbus/modbusrtuparser.h"

#include <algorithm>

using namespace dd;
using Parser = ModbusRtuStreamParser;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::initialise();
    fuzz::FuzzInput in(data, size);
    const quint8 control = in.byte();
    const Parser::Mode mode = (control & 1) ? Parser::Mode::Replies : Parser::Mode::Requests;
    const int capSelector = control >> 1;
    const int cap = capSelector == 0 ? Parser::DefaultBufferCap : Parser::MinBufferCap + capSelector;
    const qsizetype chunk = 1 + in.byte();
    const bool segments = in.byte() & 1;
    const QByteArray stream = segments ? fuzz::segmentsWithCrc(in) : in.rest();

    Parser parser(mode, cap);
    DD_FUZZ_CHECK(parser.bufferCap() == cap);
    quint64 delivered = 0;
    for (qsizetype at = 0; at < stream.size(); at += chunk) {
        parser.feed(stream.mid(at, chunk));
        DD_FUZZ_CHECK(parser.pendingBytes() < cap);
        while (parser.hasFrame()) {
            const QByteArray frame = parser.takeFrame();
            DD_FUZZ_CHECK(frame.size() >= 5 && frame.size() <= cap);
            DD_FUZZ_CHECK(hasValidCrc16(frame));
            const Parser::FrameCheck c = Parser::checkFrame(frame, mode, cap);
            DD_FUZZ_CHECK(c.state == Parser::FrameState::Complete && c.offset == 0 && c.length == frame.size());
            DD_FUZZ_CHECK(stream.contains(frame));
            delivered += static_cast<quint64>(frame.size());
        }
        DD_FUZZ_CHECK(parser.takeFrame().isEmpty());
    }
    if (parser.droppedFrames() == 0) {
        DD_FUZZ_CHECK(parser.discardedBytes() + delivered + static_cast<quint64>(parser.pendingBytes())
                      == static_cast<quint64>(stream.size()));
    }
    const qsizetype pending = parser.pendingBytes();
    DD_FUZZ_CHECK(parser.discardPending() == pending && parser.pendingBytes() == 0);

    // The link's matcher over everything received at once.
    const Parser::FrameCheck c = Parser::checkFrame(stream, mode, cap);
    DD_FUZZ_CHECK(c.offset >= 0 && c.offset <= stream.size());
    if (c.state == Parser::FrameState::Complete) {
        DD_FUZZ_CHECK(c.length >= 4 && c.offset + c.length <= stream.size());
        DD_FUZZ_CHECK(hasValidCrc16(stream.mid(c.offset, c.length)));
    } else {
        DD_FUZZ_CHECK(c.length == 0);
    }
    return 0;
}
