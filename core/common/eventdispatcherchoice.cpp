#include "core/common/eventdispatcherchoice.h"

#include <QByteArray>
#include <QtGlobal>

namespace dd {

bool preferPlainEventDispatcher()
{
#if defined(Q_OS_UNIX) && !defined(Q_OS_DARWIN)
    if (qEnvironmentVariableIsSet("QT_NO_GLIB"))
        return false;
    return qputenv("QT_NO_GLIB", QByteArray("1"));
#else
    return false;
#endif
}

} // namespace dd
