#include "core/drive/familytable.h"

#include "core/drive/servocan/servocanbackend.h"
#include "core/drive/servomodbus/servomodbusbackend.h"
#include "core/drive/shuoke/shuokebackend.h"

#include <QList>

namespace dd {

namespace {

struct BackendEntry
{
    Family family;
    FamilyBackend *(*create)(QObject *parent);
};

template <class Backend>
FamilyBackend *make(QObject *parent)
{
    return new Backend(parent);
}

} // namespace

FamilyBackend *createFamilyBackend(Family family, QObject *parent)
{
    // One line per family.
    static const QList<BackendEntry> table{
        {Family::ServoCan, &make<ServoCanBackend>},
        {Family::ServoModbus, &make<ServoModbusBackend>},
        {Family::Shuoke, &make<ShuokeBackend>},
    };
    for (const BackendEntry &e : table)
        if (e.family == family)
            return e.create(parent);
    return nullptr;
}

} // namespace dd
