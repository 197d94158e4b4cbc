// Shuoke PLC-mode codec (core/protocol/shuokeplc.h): the reply decoder (host side) judged
// against a request, and the request decoder (drive side, simulator).
// Input: [mode: bit0 = request decoder, bit1 = repair the ADU's CRC][base: u16 LE]
//        reply mode: [request address][request command][request data length % 8][data...]
//        then the ADU.
// Invariants: an accepted reply answers the request's command from an address that may
// answer it; a failure is a 5-byte exception; a success reply re-encodes to an ADU that decodes
// to the same frame. An accepted request re-encodes to an ADU that decodes the same; a read
// request re-encodes to the input exactly.

#include "tests/fuzz/shuokefuzz.h"

#include "core/protocol/shuoke/shuokeplc.h"

using namespace dd;
using namespace dd::shuoke;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::initialise();
    fuzz::FuzzInput in(data, size);
    const quint8 mode = in.byte();
    const bool requestMode = mode & 1;
    const bool repairCrc = mode & 2;
    PlcOptions options;
    options.base = in.u16();

    if (requestMode) {
        const QByteArray adu = repairCrc ? fuzz::withRepairedCrc(in.rest()) : in.rest();
        const Decoded<Frame> d = decodePlcRequest(adu, options);
        DD_FUZZ_CHECK(d.ok() != !d.error.isEmpty());
        if (!d.ok())
            return 0;
        const Frame &f = *d.value;
        DD_FUZZ_CHECK(!f.failure && f.address == static_cast<quint8>(adu.at(0)));
        const Decoded<QByteArray> encoded = encodePlcRequest(f, options);
        DD_FUZZ_CHECK(encoded.ok());
        const Decoded<Frame> re = decodePlcRequest(*encoded.value, options);
        DD_FUZZ_CHECK(re.ok() && *re.value == f);
        if (static_cast<quint8>(adu.at(1)) == PlcReadRegisters)
            DD_FUZZ_CHECK(*encoded.value == adu);
        else
            DD_FUZZ_CHECK(encoded.value->size() == adu.size() && encoded.value->left(7) == adu.left(7));
        fuzz::checkShuokeValues(f);
        return 0;
    }

    Frame request;
    request.address = in.byte();
    request.command = in.byte() & 0x7F;
    request.data = in.take(in.byte() % 8);
    const QByteArray adu = repairCrc ? fuzz::withRepairedCrc(in.rest()) : in.rest();
    const Decoded<Frame> d = decodePlcReply(adu, request, options);
    DD_FUZZ_CHECK(d.ok() != !d.error.isEmpty());
    if (!d.ok())
        return 0;
    const Frame &f = *d.value;
    DD_FUZZ_CHECK(plcRequestLayout(request, options).ok());
    DD_FUZZ_CHECK(f.command == request.command);
    DD_FUZZ_CHECK(isReplyAddress(f.address, request));
    if (f.failure) {
        DD_FUZZ_CHECK(adu.size() == 5);
    } else {
        DD_FUZZ_CHECK(adu.size() == plcReplySize(request));
        const Decoded<QByteArray> encoded = encodePlcReply(f, request, options);
        DD_FUZZ_CHECK(encoded.ok() && encoded.value->size() == adu.size());
        const Decoded<Frame> re = decodePlcReply(*encoded.value, request, options);
        DD_FUZZ_CHECK(re.ok() && *re.value == f);
    }
    fuzz::checkShuokeValues(f);
    return 0;
}
