// Shuoke RTU frame decoder (core/protocol/shuokertu.h) and the value codecs on its data.
// Input: [options: bit0 acceptLengthWithCrc, bit1 acceptFixedLength, bit2 skipHandshakeCrc,
//         bit3 repair the CRC (the frame's last two bytes)][one frame].
// Invariants: an accepted frame has a layout; a Standard frame with a valid CRC re-encodes to
// the input exactly; a FixedLength frame re-encodes (padded) to the input when the padding is
// zero; every accepted frame re-encodes to bytes that decode to the same frame.

#include "tests/fuzz/shuokefuzz.h"

#include "core/protocol/modbus/crc16.h"
#include "core/protocol/shuoke/shuokertu.h"

using namespace dd;
using namespace dd::shuoke;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::initialise();
    fuzz::FuzzInput in(data, size);
    const quint8 control = in.byte();
    const RtuOptions options = fuzz::rtuOptions(control);
    const QByteArray bytes = (control & 8) ? fuzz::withRepairedCrc(in.rest()) : in.rest();

    RtuLayout layout = static_cast<RtuLayout>(0xFF);
    const Decoded<Frame> d = decodeRtu(bytes, options, &layout);
    DD_FUZZ_CHECK(d.ok() != !d.error.isEmpty());
    if (!d.ok())
        return 0;
    const Frame &f = *d.value;
    DD_FUZZ_CHECK(layout == RtuLayout::Standard || layout == RtuLayout::LengthCountsCrc
                  || layout == RtuLayout::FixedLength);
    DD_FUZZ_CHECK(layout != RtuLayout::LengthCountsCrc || options.acceptLengthWithCrc);
    DD_FUZZ_CHECK(layout != RtuLayout::FixedLength || options.acceptFixedLength);
    DD_FUZZ_CHECK(f.address == static_cast<quint8>(bytes.at(0)));
    DD_FUZZ_CHECK(f.commandByte() == static_cast<quint8>(bytes.at(1)));

    const Decoded<QByteArray> plain = encodeRtu(f);
    DD_FUZZ_CHECK(plain.ok());
    const bool crcChecked = !(options.skipHandshakeCrc && f.command == CmdHandshake && !f.failure);
    if (layout == RtuLayout::Standard && (crcChecked || hasValidCrc16(bytes)))
        DD_FUZZ_CHECK(*plain.value == bytes);
    if (layout == RtuLayout::FixedLength) {
        RtuOptions pad;
        pad.padToFixedLength = true;
        const Decoded<QByteArray> padded = encodeRtu(f, pad);
        DD_FUZZ_CHECK(padded.ok() && padded.value->size() == kFixedFrameSize);
        const QByteArray padding = bytes.mid(3 + f.payload().size(), kFixedDataSize - f.payload().size());
        if (padding.count('\0') == padding.size())
            DD_FUZZ_CHECK(*padded.value == bytes);
    }
    RtuLayout again = RtuLayout::FixedLength;
    const Decoded<Frame> re = decodeRtu(*plain.value, options, &again);
    DD_FUZZ_CHECK(re.ok() && *re.value == f && again == RtuLayout::Standard);

    fuzz::checkShuokeValues(f);
    return 0;
}
