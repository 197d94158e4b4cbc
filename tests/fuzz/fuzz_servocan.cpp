// servo-can frame decoder (core/protocol/servocan.h).
// Input: [flags: bit0 = extended][id: u32 LE, masked to 29 bits][data bytes (any count)].
// Invariants for an accepted frame: the station is the ID's; re-encoding the decoded fields
// gives the input's data (b7 is always re-encoded as 0xFF, and reservedByteOk says whether
// the input had that); a parameter frame re-encodes through its dedicated encoder; a read
// frame is the reply to itself.

#include "tests/fuzz/fuzzsupport.h"

#include "core/protocol/servocan/servocan.h"

using namespace dd;
using namespace dd::servocan;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::initialise();
    fuzz::FuzzInput in(data, size);
    CanFrameData f;
    f.extended = (in.byte() & 1) != 0;
    f.id = in.u32() & 0x1FFFFFFFu;
    f.data = in.rest();

    const Decoded<Message> d = decode(f);
    DD_FUZZ_CHECK(d.ok() != !d.error.isEmpty());
    if (!d.ok())
        return 0;
    const Message &m = *d.value;
    DD_FUZZ_CHECK(!f.extended && f.data.size() == kFrameLength);
    DD_FUZZ_CHECK(isValidStation(m.station) && frameId(m.station) == f.id);
    DD_FUZZ_CHECK(m.reservedByteOk == (static_cast<quint8>(f.data.at(7)) == kReservedByte));
    for (int i = 0; i < kFrameLength; ++i)
        DD_FUZZ_CHECK(m.raw[size_t(i)] == static_cast<quint8>(f.data.at(i)));

    QByteArray expected = f.data;
    expected[7] = static_cast<char>(kReservedByte);
    const CanFrameData again = frame(m.station, m.command, m.b2, m.value);
    DD_FUZZ_CHECK(again.id == f.id && !again.extended && again.data == expected);

    if (m.isParameterFrame()) {
        DD_FUZZ_CHECK(isValidParameterIndex(m.paramIndex));
        QByteArray paramExpected = expected;
        paramExpected[4] = 0; // b4 is documented as 0 and not checked on receive
        const CanFrameData p = m.command == Command::Write ? writeParameter(m.station, m.paramIndex, m.paramValue)
                                                           : readReplyParameter(m.station, m.paramIndex, m.paramValue);
        DD_FUZZ_CHECK(p.data == paramExpected);
    }
    if (const std::optional<ReadType> t = m.readType()) {
        DD_FUZZ_CHECK(isReplyTo(m, m));
        const ReadTypeInfo info = readTypeInfo(*t);
        DD_FUZZ_CHECK(info.type == *t && info.key != nullptr);
        (void)scaledValue(*t, m.value);
    } else {
        DD_FUZZ_CHECK(m.command != Command::Read);
    }
    DD_FUZZ_CHECK(!commandName(m.command).isEmpty());
    (void)commandDirection(m.command);
    (void)m.alarmCode();
    return 0;
}
