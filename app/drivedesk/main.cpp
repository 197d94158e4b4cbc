// drivedesk: the commissioning workbench (GUI).
#include "core/common/coreresources.h"
#include "core/common/localtimezone.h"
#include "ui/bus/connectrequest.h"
#include "ui/shell/commandlinefile.h"
#include "ui/shell/languagemanager.h"
#include "ui/shell/mainwindow.h"
#include "ui/workspace/driveworkspace.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QSettings>
#include <QTimer>
#include <cstdlib>
#include <optional>

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
    QString connect; // a serial port, "plugin:interface", or "last"
    QString family;  // a family id or "detect"
    int baud = 0;
    int bitrate = 0;
    QString framing;
    QString panel;      // the drive tab to show first
    QString drive;      // select the first drive of this family
    QString screenshot; // grab the window into this PNG and quit
    QString file;       // a backup or run file to open (drivedesk FILE: the desktop's "Open with")
    int screenshotDelayMs = 3000;
};

// Parses the command line; exits (help, version, errors) like any Qt tool.
Options parseOptions(const QApplication &app)
{
    QCommandLineParser p;
    p.setApplicationDescription(
        dd::DriveDeskMain::tr("DriveDesk: commissioning workbench for servo and stepper drives."));
    p.addHelpOption();
    p.addVersionOption();
    const QCommandLineOption demo(
        QStringLiteral("demo"),
        dd::DriveDeskMain::tr("Start the simulated bench (one drive of each family) and connect to it."));
    const QCommandLineOption lang(QStringLiteral("lang"),
                                  dd::DriveDeskMain::tr("User-interface language for this session: en, zh_CN or system "
                                                        "(default: the Language menu's choice)."),
                                  QStringLiteral("language"));
    const QCommandLineOption connect(
        QStringLiteral("connect"),
        dd::DriveDeskMain::tr("Connect at start-up and scan: a serial port (/dev/ttyUSB0, COM3), "
                              "a CAN interface as plugin:interface (socketcan:can0), or 'last' for "
                              "the connection used last."),
        QStringLiteral("link"));
    const QCommandLineOption family(
        QStringLiteral("family"),
        dd::DriveDeskMain::tr("With --connect: %1 or detect (default).").arg(dd::familyIds().join(QStringLiteral(", "))),
        QStringLiteral("family"));
    const QCommandLineOption baud(
        QStringLiteral("baud"),
        dd::DriveDeskMain::tr("With --connect on a serial port: the baud rate (default: the family's)."),
        QStringLiteral("rate"));
    const QCommandLineOption bitrate(
        QStringLiteral("bitrate"),
        dd::DriveDeskMain::tr("With --connect on CAN: the bitrate in bit/s (default: the family's)."),
        QStringLiteral("rate"));
    const QCommandLineOption framing(QStringLiteral("framing"),
                                     dd::DriveDeskMain::tr("With --family shuoke: rtu, ascii, plc or can."),
                                     QStringLiteral("framing"));
    const QCommandLineOption panel(
        QStringLiteral("panel"), dd::DriveDeskMain::tr("The tab to show for the selected drive: overview, trend, ..."),
        QStringLiteral("id"));
    const QCommandLineOption drive(QStringLiteral("drive"),
                                   dd::DriveDeskMain::tr("Select the first drive of this family that is found: %1.")
                                       .arg(dd::familyIds().join(QStringLiteral(", "))),
                                   QStringLiteral("family"));
    const QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        dd::DriveDeskMain::tr("Save a picture of the main window to this PNG file after the delay, "
                              "then quit (documentation)."),
        QStringLiteral("file"));
    const QCommandLineOption delay(QStringLiteral("screenshot-delay"),
                                   dd::DriveDeskMain::tr("Seconds to wait before --screenshot (default 3)."),
                                   QStringLiteral("seconds"), QStringLiteral("3"));
    p.addOptions({demo, lang, connect, family, baud, bitrate, framing, panel, drive, screenshot, delay});
    p.addPositionalArgument(
        QStringLiteral("file"),
        dd::DriveDeskMain::tr("A backup or run file: it is added to File > Recent files and opens in the drive's "
                              "tabs when a drive is selected."),
        QStringLiteral("[file]"));
    p.process(app);

    Options o;
    o.demo = p.isSet(demo);
    o.lang = p.value(lang);
    o.connect = p.value(connect);
    o.family = p.value(family);
    o.baud = p.value(baud).toInt();
    o.bitrate = p.value(bitrate).toInt();
    o.framing = p.value(framing);
    o.panel = p.value(panel);
    o.drive = p.value(drive);
    o.screenshot = p.value(screenshot);
    o.screenshotDelayMs = qMax(0, int(p.value(delay).toDouble() * 1000));
    const QStringList files = p.positionalArguments();
    if (files.size() > 1) {
        qCritical("%s", qPrintable(dd::DriveDeskMain::tr("Give one file at most (%1 given).").arg(files.size())));
        std::exit(2);
    }
    o.file = files.value(0);
    return o;
}

// The --lang argument, looked for by hand: the language must be set before
// QCommandLineParser runs, so that --help is translated too.
QString languageArgument(const QStringList &args)
{
    QString lang;
    for (int i = 1; i < args.size(); ++i) {
        if (args.at(i) == QLatin1String("--lang") && i + 1 < args.size())
            lang = args.at(i + 1);
        else if (args.at(i).startsWith(QLatin1String("--lang=")))
            lang = args.at(i).mid(7);
    }
    return lang;
}

// What --connect asks for (nothing without it); false after saying why it cannot be used.
bool connectRequest(const Options &options, std::optional<dd::ConnectRequest> *request)
{
    if (options.connect == QLatin1String("last")) {
        QSettings settings;
        *request = dd::ConnectRequest::load(settings);
    } else if (!options.connect.isEmpty()) {
        dd::ConnectRequest r;
        QString error;
        if (!dd::ConnectRequest::fromCommandLine(options.connect, options.family, options.baud, options.bitrate,
                                                 options.framing, &r, &error)) {
            qCritical("%s", qPrintable(error));
            return false;
        }
        *request = r;
    }
    return true;
}

// The family of --drive (nothing without it); false after saying why it cannot be used.
bool preferredFamily(const Options &options, std::optional<dd::Family> *family)
{
    if (options.drive.isEmpty())
        return true;
    *family = dd::familyFromId(options.drive);
    if (!*family) {
        qCritical("%s",
                  qPrintable(dd::DriveDeskMain::tr("Unknown family '%1' for --drive: use %2.")
                                 .arg(options.drive, dd::familyIds().join(QStringLiteral(", ")))));
        return false;
    }
    return true;
}

// --screenshot: grabs the window into the file after the delay and quits.
void scheduleScreenshot(dd::MainWindow &window, const Options &options)
{
    QTimer::singleShot(options.screenshotDelayMs, &window, [&window, &options] {
        const bool ok = window.grab().save(options.screenshot, "PNG");
        if (!ok)
            qCritical("Could not write %s", qPrintable(options.screenshot));
        QCoreApplication::exit(ok ? 0 : 1);
    });
}

} // namespace

int main(int argc, char *argv[])
{
    dd::pinLocalTimeZone(); // before any thread: see localtimezone.h
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("DriveDesk"));
    QCoreApplication::setOrganizationDomain(QStringLiteral("drivedesk.invalid"));
    QCoreApplication::setApplicationName(QStringLiteral("drivedesk"));
    QCoreApplication::setApplicationVersion(QStringLiteral(DRIVEDESK_VERSION));
    QGuiApplication::setApplicationDisplayName(QStringLiteral("DriveDesk"));
    QGuiApplication::setDesktopFileName(QStringLiteral("io.github.drivedesk.DriveDesk"));
    QIcon fallbackIcon;
    for (int size : {32, 64, 256})
        fallbackIcon.addFile(QStringLiteral(":/icons/drivedesk-%1.png").arg(size));
    QApplication::setWindowIcon(QIcon::fromTheme(QStringLiteral("io.github.drivedesk.DriveDesk"), fallbackIcon));
    dd::ensureCoreResources();

    // The language first, so that --help is translated too.
    const QString langArg = languageArgument(app.arguments());
    bool langOk = true;
    const auto chosen = dd::LanguageManager::languageFromId(langArg, &langOk);
    dd::LanguageManager language;
    language.apply(langArg.isEmpty() ? dd::LanguageManager::savedLanguage() : chosen);
    const Options options = parseOptions(app);
    if (!langOk)
        qWarning("Unknown language '%s': use en, zh_CN or system", qPrintable(langArg));

    // --connect and --drive are checked before any window opens.
    std::optional<dd::ConnectRequest> request;
    std::optional<dd::Family> family;
    if (!connectRequest(options, &request) || !preferredFamily(options, &family))
        return 2;
    if (!options.file.isEmpty()) {
        const QString problem = dd::CommandLineFile::checkReadable(options.file);
        if (!problem.isEmpty()) {
            qCritical("%s", qPrintable(problem));
            return 2;
        }
    }

    dd::MainWindow window(&language); // --lang holds for this session only: not saved
    if (family)
        window.setPreferredFamily(*family);
    window.restoreLayout();
    if (!options.panel.isEmpty())
        window.workspace()->setPreferredPanel(options.panel);
    window.show();
    if (!options.file.isEmpty())
        new dd::CommandLineFile(&window, options.file); // owned by the window
    if (options.demo)
        window.startDemo();
    if (request)
        window.connectTo(*request);
    if (!options.screenshot.isEmpty())
        scheduleScreenshot(window, options);
    return app.exec();
}
