#include "drive/driveconnection.h"
#include "drive/familybackend.h"
#include "drive/shuokebackend.h"

namespace dd {

// One place that knows every family's backend class.
FamilyBackend *createFamilyBackend(Family family, QObject *parent)
{
    switch (family) {
    case Family::Shuoke:
        return new ShuokeBackend(parent);
    case Family::ServoCan:
    case Family::ServoModbus:
        break;
    }
    return nullptr;
}

} // namespace dd
