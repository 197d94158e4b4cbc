#include "core/common/timerslack.h"

#include <QtGlobal>

#ifdef Q_OS_LINUX
#include <sys/prctl.h>
#endif

namespace dd {

bool tightenTimerSlack()
{
#ifdef Q_OS_LINUX
    thread_local bool tightened = false;
    if (!tightened)
        tightened = prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL) == 0; // 1 ns: as tight as it goes
    return tightened;
#else
    return false;
#endif
}

} // namespace dd
