#include "core/protocol/familytraits.h"

#include "core/protocol/shuoke/shuokedescriber.h"

namespace dd::shuoke {

// The shuoke family's traits (docs/protocols/shuoke.md): four framings of one command set.
// Serial addresses 1..247, CAN IDs 1..250. The baud sweep is the seed's baud codes 1..8
// (57600 is a reserved code), most common first. PLC mode is not auto-detected: its
// register base is a drive setting (0x3F) that has to be known.
const FamilyTraits &traits()
{
    static const FamilyTraits t{
        Family::Shuoke,
        QT_TRANSLATE_NOOP("dd::FamilyTraits", "Shuoke stepper"),
        {
            {QStringLiteral("rtu"),
             QT_TRANSLATE_NOOP("dd::FamilyTraits", "RTU (binary)"),
             LinkKind::Serial,
             {1, 247},
             true},
            {QStringLiteral("ascii"), QT_TRANSLATE_NOOP("dd::FamilyTraits", "ASCII"), LinkKind::Serial, {1, 247}, true},
            {QStringLiteral("plc"),
             QT_TRANSLATE_NOOP("dd::FamilyTraits", "PLC mode (Modbus registers)"),
             LinkKind::Serial,
             {1, 247},
             false},
            {QStringLiteral("can"), QT_TRANSLATE_NOOP("dd::FamilyTraits", "CAN"), LinkKind::Can, {1, 250}, true},
        },
        9600,
        {9600, 19200, 38400, 4800, 2400, 1200, 600, 300},
        100000,
        QT_TRANSLATE_NOOP("dd::FamilyTraits", "pulses/s"),
        QT_TRANSLATE_NOOP("dd::FamilyTraits", "pulses"),
        100000, // pulses/s: the seed's 0..100000; the drive answers 0x04 beyond
        1000,
        2000,
        false,
        ParameterAddressing::ReadCommand,
        [](const QString &framing, const QVariantMap &options) -> std::unique_ptr<FrameDescriber> {
            return std::make_unique<ShuokeDescriber>(framing, options);
        },
    };
    return t;
}

} // namespace dd::shuoke
