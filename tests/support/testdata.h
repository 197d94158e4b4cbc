#pragma once

#include <QString>

namespace dd::test {

// tests/data: from DRIVEDESK_SOURCE_DIR (set by ctest), else above the executable.
QString dataDir();

} // namespace dd::test
