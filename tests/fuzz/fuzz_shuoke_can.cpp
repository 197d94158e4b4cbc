// Shuoke CAN frame decoder (core/protocol/shuokecan.h) and the value codecs on its data.
// Input: [flags: bit0 = extended][id: u32 LE, masked to 29 bits][data bytes (any count)].
// Invariants: an accepted frame's identifier is its address (or 0 when extended); re-encoding
// gives the same identifier and the input's [addr][cmd][len][data] bytes, padded to 8.

#include "tests/fuzz/shuokefuzz.h"

#include "core/protocol/shuoke/shuokecan.h"

using namespace dd;
using namespace dd::shuoke;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::initialise();
    fuzz::FuzzInput in(data, size);
    CanFrameData can;
    can.extended = (in.byte() & 1) != 0;
    can.id = in.u32() & 0x1FFFFFFFu;
    can.data = in.rest();

    const Decoded<Frame> d = decodeCan(can);
    DD_FUZZ_CHECK(d.ok() != !d.error.isEmpty());
    if (!d.ok())
        return 0;
    const Frame &f = *d.value;
    DD_FUZZ_CHECK(can.data.size() >= 3 && can.data.size() <= kCanFrameBytes);
    DD_FUZZ_CHECK(can.id == f.address || (can.extended && can.id == 0));

    CanOptions options;
    options.extended = can.extended;
    options.extendedId = (can.extended && can.id != f.address) ? CanExtendedId::Zero : CanExtendedId::Address;
    const Decoded<CanFrameData> encoded = encodeCan(f, options);
    DD_FUZZ_CHECK(encoded.ok());
    DD_FUZZ_CHECK(encoded.value->id == can.id && encoded.value->extended == can.extended);
    DD_FUZZ_CHECK(encoded.value->data.size() == kCanFrameBytes);
    const qsizetype used = 3 + f.payload().size();
    DD_FUZZ_CHECK(encoded.value->data.left(used) == can.data.left(used));
    const Decoded<Frame> re = decodeCan(*encoded.value);
    DD_FUZZ_CHECK(re.ok() && *re.value == f);

    fuzz::checkShuokeValues(f);
    return 0;
}
