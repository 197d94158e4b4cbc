#pragma once

#include <QString>

namespace dd {
class SimCanBus;
class VirtualCanHub;
} // namespace dd

namespace dd::test {

// Opens `bus` (its devices already added) on interface `interfaceName` of a started
// VirtualCanHub, waits up to 5 s until it is connected and gives its socket low delay.
// Empty when it worked, else what failed.
QString connectSimCanBus(SimCanBus *bus, const QString &interfaceName);

} // namespace dd::test
