#include "core/protocol/familytraits.h"

#include "core/protocol/servomodbus/servomodbusdescriber.h"

namespace dd::servomodbus {

// The servo-modbus family's traits (docs/protocols/servo-modbus.md): Modbus RTU on RS485,
// addresses 1..247 (PA51), EEPROM operations.
const FamilyTraits &traits()
{
    static const FamilyTraits t{
        Family::ServoModbus,
        QT_TRANSLATE_NOOP("dd::FamilyTraits", "Servo (Modbus)"),
        {{QStringLiteral("rtu"),
          QT_TRANSLATE_NOOP("dd::FamilyTraits", "RTU (binary)"),
          LinkKind::Serial,
          {1, 247},
          true}},
        19200,
        {9600, 19200, 38400, 57600, 115200},
        0,
        QT_TRANSLATE_NOOP("dd::FamilyTraits", "r/min"),
        QT_TRANSLATE_NOOP("dd::FamilyTraits", "counts"),
        6000,
        100,
        300,
        true,
        ParameterAddressing::Register,
        [](const QString &, const QVariantMap &) -> std::unique_ptr<FrameDescriber> {
            return std::make_unique<ServoModbusDescriber>();
        },
    };
    return t;
}

} // namespace dd::servomodbus
