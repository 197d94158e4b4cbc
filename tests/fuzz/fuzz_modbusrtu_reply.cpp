// Modbus RTU reply decoder, host side (core/protocol/modbusrtu.h), judged against a request;
// the servo-modbus position pairs (core/protocol/servomodbus.h) on the registers it returns.
// Input: [flags: bit0 = repair the CRC][address][function selector][start: u16 LE][count: u16 LE]
//        [reply ADU].
// The function selector picks 0x03 / 0x06 / 0x10 (selector % 4 == 0..2) or uses the raw byte.
// Invariants: a reason is given exactly when the decode fails; an accepted reply matches the
// request (address unless exception, function, count and echo) and, when the request is one
// the encoder can send (1..125 registers for 0x03), re-encodes to the input.

#include "tests/fuzz/fuzzsupport.h"

#include "core/protocol/modbus/modbusrtu.h"
#include "core/protocol/servomodbus/servomodbus.h"

using namespace dd;
using namespace dd::modbusrtu;

namespace {

void checkPositionPairs(const QList<quint16> &values)
{
    using namespace dd::servomodbus;
    for (qsizetype i = 0; i + 1 < values.size(); i += 2) {
        const quint16 low = values.at(i);
        const quint16 high = values.at(i + 1);
        const qint64 binary = combinePositionPair(low, high, PositionPairRule::BinaryWords);
        const std::optional<RegisterPair> split = splitPosition(binary, PositionPairRule::BinaryWords);
        DD_FUZZ_CHECK(split && split->low == low && split->high == high);
        for (PositionPairRule rule : {PositionPairRule::Decimal10000, PositionPairRule::Decimal100000}) {
            const qint64 v = combinePositionPair(low, high, rule);
            if (const std::optional<RegisterPair> p = splitPosition(v, rule))
                DD_FUZZ_CHECK(combinePositionPair(p->low, p->high, rule) == v);
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::initialise();
    fuzz::FuzzInput in(data, size);
    const bool repairCrc = in.byte() & 1;
    Request request;
    request.address = in.byte();
    const quint8 selector = in.byte();
    static const quint8 functions[] = {ReadHoldingRegisters, WriteSingleRegister, WriteMultipleRegisters};
    request.function = selector % 4 < 3 ? functions[selector % 4] : selector;
    request.start = in.u16();
    request.count = in.u16();
    const QByteArray adu = repairCrc ? fuzz::withRepairedCrc(in.rest()) : in.rest();

    DecodeError reason = DecodeError::TooShort;
    const Decoded<Reply> d = decodeReply(adu, request, &reason);
    DD_FUZZ_CHECK(d.ok() == (reason == DecodeError::None));
    DD_FUZZ_CHECK(d.ok() != !d.error.isEmpty());
    if (!d.ok())
        return 0;
    const Reply &r = *d.value;
    DD_FUZZ_CHECK(request.address != BroadcastAddress);
    DD_FUZZ_CHECK(r.function == request.function);
    DD_FUZZ_CHECK(r.address == static_cast<quint8>(adu.at(0)));
    if (r.isException) {
        DD_FUZZ_CHECK(adu.size() == ExceptionReplySize);
        DD_FUZZ_CHECK(encodeExceptionReply(r.address, r.function, r.exceptionCode) == adu);
        DD_FUZZ_CHECK(!exceptionCodeName(r.exceptionCode).isEmpty());
        return 0;
    }
    DD_FUZZ_CHECK(r.address == request.address);
    switch (r.function) {
    case ReadHoldingRegisters:
        DD_FUZZ_CHECK(r.count == request.count && r.values.size() == r.count);
        DD_FUZZ_CHECK(adu.size() == expectedReplySize(request));
        // Requests for 0 or more than 125 registers are never sent (the encoder refuses
        // them), so a reply to one needs no round trip.
        if (request.count >= 1 && request.count <= StandardMaxReadCount)
            DD_FUZZ_CHECK(encodeReadHoldingReply(r.address, r.values) == adu);
        checkPositionPairs(r.values);
        break;
    case WriteSingleRegister:
        DD_FUZZ_CHECK(r.start == request.start && r.count == 1 && r.values.size() == 1);
        DD_FUZZ_CHECK(encodeWriteSingleReply(r.address, r.start, r.values.at(0)) == adu);
        for (const servomodbus::EeOp op : servomodbus::allEeOps())
            (void)servomodbus::interpretLegacyEeReply(r.values.at(0), op);
        break;
    case WriteMultipleRegisters:
        DD_FUZZ_CHECK(r.start == request.start && r.count == request.count && r.values.isEmpty());
        DD_FUZZ_CHECK(encodeWriteMultipleReply(r.address, r.start, r.count) == adu);
        break;
    default: DD_FUZZ_CHECK(false && "reply accepted for an unknown function");
    }
    return 0;
}
