// drivedesk-cli: the scriptable commissioning tool. See `drivedesk-cli --help`.
#include "cli.h"

#include "common/coreresources.h"

#include <QCoreApplication>
#include <QLocale>
#include <QTranslator>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("drivedesk-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(DRIVEDESK_VERSION));

    QTranslator translator;
    if (translator.load(QLocale(), QStringLiteral("drivedesk"), QStringLiteral("_"),
                        QStringLiteral(":/i18n")))
        QCoreApplication::installTranslator(&translator);

    dd::ensureCoreResources();
    dd::Cli cli;
    return cli.run(QCoreApplication::arguments().mid(1));
}
