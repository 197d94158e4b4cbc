// drivedesk: the commissioning workbench (GUI).
#include "common/coreresources.h"
#include "connectrequest.h"
#include "languagemanager.h"
#include "mainwindow.h"

#include <QApplication>
#include <QCanBus>
#include <QCommandLineParser>
#include <QSettings>
#include <QTimer>

namespace dd {
// The translation context of this file's texts.
struct DriveDeskMain
{
    Q_DECLARE_TR_FUNCTIONS(dd::DriveDeskMain)
};
} // namespace dd

namespace {

struct Options
{
    bool demo = false;
    QString lang;
    QString connect;          // a serial port, "plugin:interface", or "last"
    QString family;           // a family id or "detect"
    int baud = 0;
    int bitrate = 0;
    QString framing;
    QString screenshot;       // grab the window into this PNG and quit
    int screenshotDelayMs = 3000;
};

// Parses the command line; exits (help, version, errors) like any Qt tool.
Options parseOptions(const QApplication &app)
{
    QCommandLineParser p;
    p.setApplicationDescription(dd::DriveDeskMain::tr(
        "DriveDesk: commissioning workbench for servo and stepper drives."));
    p.addHelpOption();
    p.addVersionOption();
    const QCommandLineOption demo(QStringLiteral("demo"),
        dd::DriveDeskMain::tr("Start the simulated bench (one drive of each family) and connect to it."));
    const QCommandLineOption lang(QStringLiteral("lang"),
        dd::DriveDeskMain::tr("User-interface language for this session: en, zh_CN or system "
                                         "(default: the Language menu's choice)."),
        QStringLiteral("language"));
    const QCommandLineOption connect(QStringLiteral("connect"),
        dd::DriveDeskMain::tr("Connect at start-up and scan: a serial port (/dev/ttyUSB0, COM3), "
                                         "a CAN interface as plugin:interface (socketcan:can0), or 'last' for "
                                         "the connection used last."),
        QStringLiteral("link"));
    const QCommandLineOption family(QStringLiteral("family"),
        dd::DriveDeskMain::tr("With --connect: servo-can, servo-modbus, shuoke or detect (default)."),
        QStringLiteral("family"), QStringLiteral("detect"));
    const QCommandLineOption baud(QStringLiteral("baud"),
        dd::DriveDeskMain::tr("With --connect on a serial port: the baud rate (default: the family's)."),
        QStringLiteral("rate"));
    const QCommandLineOption bitrate(QStringLiteral("bitrate"),
        dd::DriveDeskMain::tr("With --connect on CAN: the bitrate in bit/s (default: the family's)."),
        QStringLiteral("rate"));
    const QCommandLineOption framing(QStringLiteral("framing"),
        dd::DriveDeskMain::tr("With --family shuoke: rtu, ascii, plc or can."),
        QStringLiteral("framing"));
    const QCommandLineOption screenshot(QStringLiteral("screenshot"),
        dd::DriveDeskMain::tr("Save a picture of the main window to this PNG file after the delay, "
                                         "then quit (documentation)."),
        QStringLiteral("file"));
    const QCommandLineOption delay(QStringLiteral("screenshot-delay"),
        dd::DriveDeskMain::tr("Seconds to wait before --screenshot (default 3)."),
        QStringLiteral("seconds"), QStringLiteral("3"));
    p.addOptions({demo, lang, connect, family, baud, bitrate, framing, screenshot, delay});
    p.process(app);

    Options o;
    o.demo = p.isSet(demo);
    o.lang = p.value(lang);
    o.connect = p.value(connect);
    o.family = p.value(family);
    o.baud = p.value(baud).toInt();
    o.bitrate = p.value(bitrate).toInt();
    o.framing = p.value(framing);
    o.screenshot = p.value(screenshot);
    o.screenshotDelayMs = qMax(0, int(p.value(delay).toDouble() * 1000));
    if (!o.family.isEmpty() && o.family != QLatin1String("detect") && !dd::familyFromId(o.family)) {
        qCritical("%s", qPrintable(dd::DriveDeskMain::tr("Unknown family '%1'; use one of: %2, detect.")
                                       .arg(o.family, dd::familyIds().join(QStringLiteral(", ")))));
        ::exit(2);
    }
    return o;
}

dd::ConnectRequest requestFrom(const Options &o)
{
    QSettings settings;
    dd::ConnectRequest r = dd::ConnectRequest::load(settings);
    if (o.connect == QLatin1String("last"))
        return r;
    r.settings = {};
    r.detect = o.family.isEmpty() || o.family == QLatin1String("detect");
    r.settings.family = dd::familyFromId(o.family).value_or(dd::Family::ServoModbus);
    // "plugin:interface" when the part before the colon names a Qt CAN plugin.
    const QString plugin = o.connect.section(QLatin1Char(':'), 0, 0);
    if (o.connect.contains(QLatin1Char(':')) && QCanBus::instance()->plugins().contains(plugin))
        r.settings.can = o.connect;
    else
        r.settings.port = o.connect;
    r.settings.baud = o.baud;
    r.settings.bitrate = o.bitrate;
    r.settings.framing = o.framing;
    r.scan = true;
    return r;
}

} // namespace

int main(int argc, char *argv[])
{
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("DriveDesk"));
    QCoreApplication::setOrganizationDomain(QStringLiteral("drivedesk.invalid"));
    QCoreApplication::setApplicationName(QStringLiteral("drivedesk"));
    QCoreApplication::setApplicationVersion(QStringLiteral(DRIVEDESK_VERSION));
    QGuiApplication::setApplicationDisplayName(QStringLiteral("DriveDesk"));
    dd::ensureCoreResources();

    // The language first, so that --help is translated too.
    dd::LanguageManager language;
    const QString langArg = [&] {
        const QStringList args = app.arguments();
        const int i = args.indexOf(QStringLiteral("--lang"));
        return i >= 0 && i + 1 < args.size() ? args.at(i + 1) : QString();
    }();
    language.apply(langArg.isEmpty() ? dd::LanguageManager::savedLanguage()
                                     : dd::LanguageManager::languageFromId(langArg));
    const Options options = parseOptions(app);

    if (!options.lang.isEmpty()) {
        bool ok = false;
        dd::LanguageManager::languageFromId(options.lang, &ok);
        if (!ok)
            qWarning("Unknown language '%s': use en, zh_CN or system", qPrintable(options.lang));
    }

    dd::MainWindow window(&language);   // --lang holds for this session only: not saved
    window.restoreLayout();
    window.show();

    if (options.demo)
        window.startDemo();
    if (!options.connect.isEmpty())
        window.connectTo(requestFrom(options));
    if (!options.screenshot.isEmpty()) {
        QTimer::singleShot(options.screenshotDelayMs, &window, [&window, &options] {
            const bool ok = window.grab().save(options.screenshot, "PNG");
            if (!ok)
                qCritical("Could not write %s", qPrintable(options.screenshot));
            QCoreApplication::exit(ok ? 0 : 1);
        });
    }
    return app.exec();
}
