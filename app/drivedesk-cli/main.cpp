// drivedesk-cli: the scriptable commissioning tool. See `drivedesk-cli --help`.
#include "cli/cli.h"

#include "core/common/coreresources.h"
#include "core/common/eventdispatcherchoice.h"
#include "core/common/localtimezone.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <memory>

int main(int argc, char *argv[])
{
    dd::pinLocalTimeZone();           // before any thread: see localtimezone.h
    dd::preferPlainEventDispatcher(); // before the application object: see eventdispatcherchoice.h
    QStringList arguments;
    for (int i = 1; i < argc; ++i)
        arguments << QString::fromLocal8Bit(argv[i]);
    // `report` sets text and writes a PDF: that needs Qt Gui (fonts), but never a display.
    std::unique_ptr<QCoreApplication> app;
    if (dd::Cli::needsGuiApplication(arguments)) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
        app = std::make_unique<QGuiApplication>(argc, argv);
    } else {
        app = std::make_unique<QCoreApplication>(argc, argv);
    }
    QCoreApplication::setApplicationName(QStringLiteral("drivedesk-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(DRIVEDESK_VERSION));

    dd::ensureCoreResources();
    dd::Cli cli; // it installs the translation (--lang, else the locale)
    return cli.run(QCoreApplication::arguments().mid(1));
}
