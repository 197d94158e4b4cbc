// Shuoke ASCII line decoder (core/protocol/shuokeascii.h) and the value codecs on its data.
// Input: [options: bit0 check = two's complement, bit1 acceptLengthPlusOne, bit2 repair the check
//         byte][one line].
// Invariants: an accepted line re-encodes to bytes that decode to the same frame; a line in
// the canonical form (upper-case hex, CR LF, len = data bytes) re-encodes to itself.

#include "tests/fuzz/shuokefuzz.h"

#include "core/protocol/shuoke/shuokeascii.h"

using namespace dd;
using namespace dd::shuoke;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::initialise();
    fuzz::FuzzInput in(data, size);
    const quint8 control = in.byte();
    const AsciiOptions options = fuzz::asciiOptions(control);
    const QByteArray line = (control & 4) ? fuzz::withRepairedAsciiCheck(in.rest(), options.check) : in.rest();

    const Decoded<Frame> d = decodeAscii(line, options);
    DD_FUZZ_CHECK(d.ok() != !d.error.isEmpty());
    if (!d.ok())
        return 0;
    const Frame &f = *d.value;
    DD_FUZZ_CHECK(line.startsWith(kAsciiStart) && line.endsWith('\n'));

    const Decoded<QByteArray> encoded = encodeAscii(f, options);
    DD_FUZZ_CHECK(encoded.ok());
    const Decoded<Frame> re = decodeAscii(*encoded.value, options);
    DD_FUZZ_CHECK(re.ok() && *re.value == f);

    const bool canonicalCase = line == line.toUpper();
    const bool crlf = line.endsWith("\r\n");
    const bool lengthIsData = line.size() >= 7
        && line.mid(5, 2).toUpper() == QByteArray::number(f.payload().size(), 16).rightJustified(2, '0').toUpper();
    if (canonicalCase && crlf && lengthIsData)
        DD_FUZZ_CHECK(*encoded.value == line);

    fuzz::checkShuokeValues(f);
    return 0;
}
