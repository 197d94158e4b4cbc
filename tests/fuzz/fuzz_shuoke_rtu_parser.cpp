// Shuoke RtuStreamParser (core/protocol/shuokertustreamparser.h).
// Input: [options: bit0 acceptLengthWithCrc, bit1 acceptFixedLength, bit2 skipHandshakeCrc,
//         bit3 use feed() instead of append() + takeFrame(), bit4 segments]
//        [capacity selector: 0 = default, else the value (raised to the minimum)]
//        [chunk: input slices of 1 + chunk bytes]
//        [byte stream, or with bit4 segments that become frames with a CRC or noise: see
//        fuzz::segmentsWithCrc()].
// Invariants: the buffer never exceeds its capacity; every frame's header and data bytes
// occur in the input (the parser invents nothing), with the length byte of its layout; with
// append() + takeFrame() no byte is lost or invented (discarded + frames + buffered == fed).

#include "tests/fuzz/shuokefuzz.h"

#include "core/protocol/shuoke/shuokertustreamparser.h"

#include <algorithm>

using namespace dd;
using namespace dd::shuoke;

namespace {

qsizetype wireSize(const Frame &f, RtuLayout layout)
{
    return layout == RtuLayout::FixedLength ? kFixedFrameSize : kRtuOverhead + f.payload().size();
}

QByteArray head(const Frame &f, int len)
{
    QByteArray out;
    out.append(static_cast<char>(f.address));
    out.append(static_cast<char>(f.commandByte()));
    out.append(static_cast<char>(len));
    out.append(f.payload());
    return out;
}

// `layout` null: frames from feed(), whose layouts are not reported one by one.
void checkFrom(const QByteArray &stream, const Frame &f, const RtuLayout *layout)
{
    const qsizetype n = f.payload().size();
    DD_FUZZ_CHECK(n <= RtuStreamParser::kMaxDataLength);
    if (layout) {
        DD_FUZZ_CHECK(stream.contains(head(f, *layout == RtuLayout::LengthCountsCrc ? n + 2 : n)));
    } else {
        DD_FUZZ_CHECK(stream.contains(head(f, n)) || stream.contains(head(f, n + 2)));
    }
    fuzz::checkShuokeValues(f);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::initialise();
    fuzz::FuzzInput in(data, size);
    const quint8 control = in.byte();
    const RtuOptions options = fuzz::rtuOptions(control);
    const bool useFeed = control & 8;
    const quint8 capacitySelector = in.byte();
    const qsizetype chunk = 1 + in.byte();
    const QByteArray stream = (control & 16) ? fuzz::segmentsWithCrc(in) : in.rest();

    RtuStreamParser parser(options, capacitySelector == 0 ? RtuStreamParser::kDefaultCapacity : capacitySelector);
    const qsizetype capacity = parser.capacity();
    DD_FUZZ_CHECK(capacity >= capacitySelector);
    quint64 taken = 0;
    for (qsizetype at = 0; at < stream.size(); at += chunk) {
        const QByteArray piece = stream.mid(at, chunk);
        if (useFeed) {
            for (const Frame &f : parser.feed(piece))
                checkFrom(stream, f, nullptr);
        } else {
            // Slices that fit the free space, as feed() does: nothing is dropped for lack of room.
            for (qsizetype i = 0; i < piece.size();) {
                const qsizetype n = std::min(piece.size() - i,
                                             std::max<qsizetype>(1, capacity - parser.bufferedSize()));
                parser.append(piece.mid(i, n));
                i += n;
                DD_FUZZ_CHECK(parser.bufferedSize() <= capacity);
                while (const std::optional<Frame> f = parser.takeFrame()) {
                    const RtuLayout layout = parser.lastLayout();
                    checkFrom(stream, *f, &layout);
                    taken += static_cast<quint64>(wireSize(*f, parser.lastLayout()));
                }
            }
        }
        DD_FUZZ_CHECK(parser.bufferedSize() <= capacity);
    }
    if (!useFeed) {
        DD_FUZZ_CHECK(parser.discardedBytes() + taken + static_cast<quint64>(parser.bufferedSize())
                      == static_cast<quint64>(stream.size()));
    }
    parser.clear();
    DD_FUZZ_CHECK(parser.bufferedSize() == 0 && !parser.takeFrame());
    return 0;
}
