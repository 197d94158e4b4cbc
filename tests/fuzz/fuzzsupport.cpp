#include "fuzzsupport.h"

#include "common/coreresources.h"

#include <QString>
#include <QtGlobal>

#include <mutex>

namespace dd::fuzz {

namespace {
void quietHandler(QtMsgType type, const QMessageLogContext &, const QString &message)
{
    if (type == QtFatalMsg || type == QtCriticalMsg)
        std::fprintf(stderr, "%s\n", qPrintable(message)); // Qt aborts after a fatal message
}
} // namespace

void initialise()
{
    static std::once_flag once;
    std::call_once(once, [] {
        qInstallMessageHandler(quietHandler);
        dd::ensureCoreResources();
    });
}

} // namespace dd::fuzz
