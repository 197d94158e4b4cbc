#include "core/protocol/familytraits.h"

#include "core/protocol/servocan/servocan.h"
#include "core/protocol/servocan/servocandescriber.h"

namespace dd::servocan {

// The servo-can family's traits (docs/protocols/servo-can.md): CAN 2.0A at the drive's
// fixed 1 Mbit/s, stations 0..99.
const FamilyTraits &traits()
{
    static const FamilyTraits t{
        Family::ServoCan,
        QT_TRANSLATE_NOOP("dd::FamilyTraits", "Servo (CAN)"),
        {{QStringLiteral("can"), QT_TRANSLATE_NOOP("dd::FamilyTraits", "CAN"), LinkKind::Can, {0, 99}, true}},
        0,
        {},
        servocan::kBitrate,
        QT_TRANSLATE_NOOP("dd::FamilyTraits", "r/min"),
        QT_TRANSLATE_NOOP("dd::FamilyTraits", "counts"),
        6000,
        100,
        300,
        false,
        ParameterAddressing::Index,
        [](const QString &, const QVariantMap &) -> std::unique_ptr<FrameDescriber> {
            return std::make_unique<ServoCanDescriber>();
        },
        true, // 0x20..0x22 enable the servo
    };
    return t;
}

} // namespace dd::servocan
