// drivedesk-cli: the scriptable commissioning tool. See `drivedesk-cli --help`.
#include "cli.h"

#include "common/coreresources.h"

#include <QCoreApplication>
#include <QLocale>
#include <QLoggingCategory>
#include <QTranslator>

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("drivedesk-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(DRIVEDESK_VERSION));

    // stderr is for the CLI's own messages and --trace; the libraries' debug chatter stays
    // off unless QT_LOGGING_RULES asks for it (the environment overrides these rules).
    QLoggingCategory::setFilterRules(QStringLiteral("drivedesk.*.debug=false\ndrivedesk.*.info=false\n"
                                                    "drivedesk.debug=false\ndrivedesk.info=false"));

    QTranslator translator;
    if (translator.load(QLocale(), QStringLiteral("drivedesk"), QStringLiteral("_"),
                        QStringLiteral(":/i18n")))
        QCoreApplication::installTranslator(&translator);

    dd::ensureCoreResources();
    dd::Cli cli;
    return cli.run(QCoreApplication::arguments().mid(1));
}
