// Shuoke AsciiStreamParser (core/protocol/shuokeasciistreamparser.h).
// Input: [options: bit0 check = two's complement, bit1 acceptLengthPlusOne, bit2 segments]
//        [capacity selector: 0 = default, else 4 x the value (raised to the minimum)]
//        [chunk: feed() slices of 1 + chunk bytes]
//        [character stream, or with bit2 segments that become valid lines or noise: see
//        fuzz::asciiSegments()].
// Invariants: the buffer never exceeds its capacity; every frame's hex form (upper-cased, len
// = data bytes or data + 1) occurs in the upper-cased input: the parser invents nothing;
// a rejected frame leaves a reason.

#include "tests/fuzz/shuokefuzz.h"

#include "core/protocol/shuoke/shuokeasciistreamparser.h"

using namespace dd;
using namespace dd::shuoke;

namespace {

QByteArray hexForm(const Frame &f, int len, AsciiCheck check)
{
    QByteArray bytes;
    bytes.append(static_cast<char>(f.address));
    bytes.append(static_cast<char>(f.commandByte()));
    bytes.append(static_cast<char>(len));
    bytes.append(f.payload());
    bytes.append(static_cast<char>(asciiCheckByte(bytes, check)));
    return kAsciiStart + bytes.toHex().toUpper();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::initialise();
    fuzz::FuzzInput in(data, size);
    const quint8 control = in.byte();
    const AsciiOptions options = fuzz::asciiOptions(control);
    const quint8 capacitySelector = in.byte();
    const qsizetype chunk = 1 + in.byte();
    const QByteArray stream = (control & 4) ? fuzz::asciiSegments(in, options.check) : in.rest();
    const QByteArray upper = stream.toUpper();

    AsciiStreamParser parser(options,
                             capacitySelector == 0 ? AsciiStreamParser::kDefaultCapacity : 4 * capacitySelector);
    const qsizetype capacity = parser.capacity();
    for (qsizetype at = 0; at < stream.size(); at += chunk) {
        for (const Frame &f : parser.feed(stream.mid(at, chunk))) {
            const int n = static_cast<int>(f.payload().size());
            DD_FUZZ_CHECK(upper.contains(hexForm(f, n, options.check))
                          || (options.acceptLengthPlusOne && upper.contains(hexForm(f, n + 1, options.check))));
            fuzz::checkShuokeValues(f);
        }
        DD_FUZZ_CHECK(parser.bufferedSize() <= capacity);
        DD_FUZZ_CHECK((parser.rejectedFrames() == 0) == parser.lastError().isEmpty());
    }
    DD_FUZZ_CHECK(parser.discardedBytes() + static_cast<quint64>(parser.bufferedSize())
                  <= static_cast<quint64>(stream.size()));
    parser.clear();
    DD_FUZZ_CHECK(parser.bufferedSize() == 0 && !parser.takeFrame());
    return 0;
}
