// drivedesk-cli: the scriptable commissioning tool. See `drivedesk-cli --help`.
#include "cli/cli.h"

#include "core/common/coreresources.h"

#include <QCoreApplication>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("drivedesk-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(DRIVEDESK_VERSION));

    dd::ensureCoreResources();
    dd::Cli cli; // it installs the translation (--lang, else the locale)
    return cli.run(QCoreApplication::arguments().mid(1));
}
