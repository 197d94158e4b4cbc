// Modbus RTU request decoder, drive side (core/protocol/modbusrtu.h), and the servo-modbus
// drive's request validation (core/protocol/servomodbus.h) on what it accepts.
// Input: [flags: bit0 = repair the CRC][maxCount selector % 126: 0 = Modbus limits][request ADU].
// Invariants: a reason is given exactly when the decode fails; an accepted request
// re-encodes to the input bytes exactly and respects the register limit.

#include "tests/fuzz/fuzzsupport.h"

#include "core/protocol/modbus/modbusrtu.h"
#include "core/protocol/servomodbus/servomodbus.h"

using namespace dd;
using namespace dd::modbusrtu;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::initialise();
    fuzz::FuzzInput in(data, size);
    const bool repairCrc = in.byte() & 1;
    const int maxCount = in.byte() % 126; // 0 = UseStandardLimit
    const QByteArray adu = repairCrc ? fuzz::withRepairedCrc(in.rest()) : in.rest();

    DecodeError reason = DecodeError::TooShort;
    const Decoded<Request> d = decodeRequest(adu, maxCount, &reason);
    DD_FUZZ_CHECK(d.ok() == (reason == DecodeError::None));
    DD_FUZZ_CHECK(d.ok() != !d.error.isEmpty());
    DD_FUZZ_CHECK(!decodeErrorName(reason).isEmpty());
    if (!d.ok())
        return 0;
    const Request &r = *d.value;
    DD_FUZZ_CHECK(isKnownFunction(r.function));
    DD_FUZZ_CHECK(r.count >= 1);
    if (maxCount > 0)
        DD_FUZZ_CHECK(r.count <= maxCount);
    const int standard = r.function == WriteMultipleRegisters ? StandardMaxWriteCount : StandardMaxReadCount;
    DD_FUZZ_CHECK(r.function == WriteSingleRegister || r.count <= standard);
    DD_FUZZ_CHECK(r.function == ReadHoldingRegisters || r.values.size() == r.count);
    DD_FUZZ_CHECK(encodeRequest(r) == adu);
    DD_FUZZ_CHECK(expectedReplySize(r) >= 7 && expectedReplySize(r) <= MaxAduSize);

    (void)servomodbus::validateRequest(r);
    return 0;
}
