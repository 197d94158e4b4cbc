#include "drive/driveconnection.h"
#include "drive/familybackend.h"

namespace dd {

// One place that knows every family's backend class.
FamilyBackend *createFamilyBackend(Family family, QObject *parent)
{
    Q_UNUSED(parent);
    switch (family) {
    case Family::ServoCan:
    case Family::ServoModbus:
    case Family::Shuoke:
        break;
    }
    return nullptr;
}

} // namespace dd
