#include "core/common/coreresources.h"

#include <QtGlobal>

// Q_INIT_RESOURCE must be used outside any namespace.
static void initDriveDeskCoreResources()
{
    Q_INIT_RESOURCE(core);
}

namespace dd {

void ensureCoreResources()
{
    static const bool initialised = (initDriveDeskCoreResources(), true);
    Q_UNUSED(initialised);
}

} // namespace dd
