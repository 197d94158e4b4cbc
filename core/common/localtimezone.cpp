#include "core/common/localtimezone.h"

#include <QFile>
#include <QtGlobal>

namespace dd {

bool pinLocalTimeZone()
{
#ifdef Q_OS_LINUX
    if (qEnvironmentVariableIsSet("TZ") || !QFile::exists(QStringLiteral("/etc/localtime")))
        return false;
    return qputenv("TZ", ":/etc/localtime");
#else
    return false;
#endif
}

} // namespace dd
