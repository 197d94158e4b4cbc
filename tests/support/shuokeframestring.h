#pragma once

#include "core/protocol/shuoke/shuokeframe.h"

namespace dd::shuoke {

// How QCOMPARE shows a Frame (found by argument-dependent lookup):
// "Frame(addr 1 cmd 0x22 02)", or "... failure 3" for a failure reply.
char *toString(const Frame &f);

} // namespace dd::shuoke
