#pragma once

#include <QString>

namespace dd {
class Drive;
}

namespace dd::test {

// The value of live channel `id` of `drive`, read now; NaN when it cannot be read within `ms`.
double readChannel(Drive *drive, const QString &id, int ms = 5000);
// Whether `drive` reports its axis running now (false when the status cannot be read).
bool readRunning(Drive *drive, int ms = 5000);

} // namespace dd::test
