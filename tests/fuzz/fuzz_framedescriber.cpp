// FrameDescriber (core/protocol/framedescriber.h): formats every frame from the wire for the
// frame monitor, traffic logs and traces, and remembers the last request (a Modbus reply is
// only understood against it), so it meets whatever a drive, a noisy line or another master
// sends.
// Input: [family % 3][framing % 4: rtu ascii plc can][options: bit0 two's-complement ASCII
// check, bit1 big-endian values], then frames until the input ends:
// [h: bit0 from the drive, bit1 CAN, bit2 extended, bit3 repair the CRC (serial), bit4 reset
// first][length][CAN: id u32 LE][length bytes].
// Invariants: no crash, leak or undefined behaviour on any sequence; every frame gets a
// non-empty description of bounded length.

#include "tests/fuzz/fuzzsupport.h"

#include "core/protocol/familytraits.h"
#include "core/protocol/framedescriber.h"

#include <QVariantMap>

using namespace dd;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz::initialise();
    fuzz::FuzzInput in(data, size);
    static const Family families[] = {Family::ServoCan, Family::ServoModbus, Family::Shuoke};
    static const char *const framings[] = {"rtu", "ascii", "plc", "can"};
    const Family family = families[in.byte() % 3];
    const QString framing = QString::fromLatin1(framings[in.byte() % 4]);
    const quint8 options = in.byte();
    QVariantMap map;
    if (options & 1)
        map.insert(QStringLiteral("shuoke.checksum"), QStringLiteral("twos-complement"));
    if (options & 2)
        map.insert(QStringLiteral("shuoke.byteOrder"), QStringLiteral("big"));
    const std::unique_ptr<FrameDescriber> describer = createFrameDescriber(family, framing, map);
    DD_FUZZ_CHECK(describer != nullptr);

    while (in.remaining() > 0) {
        const quint8 h = in.byte();
        const size_t length = in.byte();
        const FrameDescriber::Origin origin = (h & 1) ? FrameDescriber::Origin::Drive : FrameDescriber::Origin::Host;
        if (h & 16)
            describer->reset();
        QString text;
        if (h & 2) {
            CanFrameData f;
            f.extended = (h & 4) != 0;
            f.id = in.u32() & (f.extended ? 0x1FFFFFFFu : 0x7FFu);
            f.data = in.take(length);
            text = describer->describeCan(origin, f);
        } else {
            QByteArray bytes = in.take(length);
            if ((h & 8) && bytes.size() >= 3)
                bytes = fuzz::withRepairedCrc(bytes);
            text = describer->describeSerial(origin, bytes);
        }
        DD_FUZZ_CHECK(!text.isEmpty());
        DD_FUZZ_CHECK(text.size() < 100000);
    }
    return 0;
}
