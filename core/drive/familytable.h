#pragma once

#include "core/common/family.h"

class QObject;

namespace dd {

class FamilyBackend;

// The backend (client-side drive code) of a family: the one place that lists the families'
// backend classes (familytable.cpp, one line per family). The families' traits are in
// core/protocol/familytraits.h.
FamilyBackend *createFamilyBackend(Family family, QObject *parent);

} // namespace dd
