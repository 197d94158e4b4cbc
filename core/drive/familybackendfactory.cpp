#include "drive/driveconnection.h"
#include "drive/familybackend.h"
#include "drive/servocanbackend.h"
#include "drive/servomodbusbackend.h"
#include "drive/shuokebackend.h"

namespace dd {

// One place that knows every family's backend class.
FamilyBackend *createFamilyBackend(Family family, QObject *parent)
{
    switch (family) {
    case Family::ServoCan:
        return new ServoCanBackend(parent);
    case Family::ServoModbus:
        return new ServoModbusBackend(parent);
    case Family::Shuoke:
        return new ShuokeBackend(parent);
    }
    return nullptr;
}

} // namespace dd
