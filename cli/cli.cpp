#include "cli/cli.h"

#include "cli/clicommand.h"
#include "cli/clicommands.h"
#include "cli/clihelp.h"
#include "cli/clioutput.h"
#include "core/common/signalwatcher.h"

#include "core/drive/driveconnection.h"
#include "core/drive/familybackend.h" // driveconnection.h needs it complete (QPointer)
#include "core/link/traffictap.h"
#include "core/params/parameterdictionary.h"
#include "sim/bench/simbench.h"

#include <QEventLoop>
#include <QLoggingCategory>
#include <QTimer>
#include <memory>

namespace dd {

Cli::Cli(QObject *parent)
    : QObject(parent)
{
}

Cli::~Cli() = default;

void Cli::configureLogging(bool sim)
{
    QString rules = QStringLiteral("drivedesk.*.debug=false\ndrivedesk.*.info=false\n"
                                   "drivedesk.debug=false\ndrivedesk.info=false\n"
                                   "qt.canbus.*.debug=false\nqt.canbus.*.info=false\n");
    if (sim)
        rules += QStringLiteral("qt.canbus.plugins.virtualcan.warning=false\n");
    QLoggingCategory::setFilterRules(rules);
}

bool Cli::needsGuiApplication(const QStringList &arguments)
{
    const CliParser parser(CliGlobals::optionSpecs(), CliCommands::specs());
    CliInvocation inv;
    QString error;
    return parser.parse(arguments, &inv, &error) && CliCommands::needsGui(inv.command);
}

int Cli::run(const QStringList &arguments)
{
    configureLogging(false);
    // --json is honoured even for usage errors, so scripts always get a document.
    const bool json = arguments.contains(QLatin1String("--json"));
    CliOutput out(json);
    if (!applyLanguage(arguments, json, out))
        return int(CliExit::Usage);

    const CliParser parser(CliGlobals::optionSpecs(), CliCommands::specs());

    CliInvocation inv;
    QString error;
    if (!parser.parse(arguments, &inv, &error)) {
        out.failure(QString(), int(CliExit::Usage), {ErrorCode::InvalidArgument, error});
        out.note(tr("Try: drivedesk-cli --help"));
        return int(CliExit::Usage);
    }
    out.setJson(inv.has(QStringLiteral("json")));
    if (const std::optional<CliExit> code = answerWithoutCommand(inv, out))
        return int(*code);

    CliContext context;
    context.out = &out;
    if (inv.command == QLatin1String("runs") || inv.command == QLatin1String("spectrum")) {
        // Commands on run files: no link, no drive, no dictionary.
        std::unique_ptr<CliCommand> command(CliCommands::create(inv.command, &context));
        if (!command->prepare(inv, &error)) {
            out.failure(inv.command, int(CliExit::Usage), {ErrorCode::InvalidArgument, error});
            return int(CliExit::Usage);
        }
        return runCommand(command.get(), context);
    }
    context.globals.linkOptional = CliCommands::worksWithoutLink(inv);
    if (!context.globals.load(inv, &error)) {
        out.failure(inv.command, int(CliExit::Usage), {ErrorCode::InvalidArgument, error});
        return int(CliExit::Usage);
    }
    if (const std::optional<CliExit> code = loadDictionary(context, inv.command))
        return int(*code);

    std::unique_ptr<CliCommand> command(CliCommands::create(inv, &context));
    if (context.globals.addresses.size() > 1 && !command->takesManyDrives()) {
        out.failure(inv.command, int(CliExit::Usage),
                    {ErrorCode::InvalidArgument,
                     tr("\"%1\" works on one drive: give one --address. backup, restore and diff take "
                        "several (--address 1,2,5).")
                         .arg(inv.command)});
        return int(CliExit::Usage);
    }
    if (!command->prepare(inv, &error)) {
        out.failure(inv.command, int(CliExit::Usage), {ErrorCode::InvalidArgument, error});
        return int(CliExit::Usage);
    }
    return runCommand(command.get(), context);
}

bool Cli::applyLanguage(const QStringList &arguments, bool json, CliOutput &out)
{
    // The language before anything is said (also the parser's errors and --help). A --json
    // document is the same in every language, messages included: scripts parse it and logs
    // compare across machines. So with --json the CLI speaks English, whatever --lang says.
    const std::optional<QString> lang = CliLanguage::requested(arguments);
    const std::optional<CliLanguage::Language> chosen = lang ? CliLanguage::fromId(*lang)
                                                             : std::optional(CliLanguage::systemLanguage());
    const CliLanguage::Language language = json ? CliLanguage::Language::English
                                                : chosen.value_or(CliLanguage::systemLanguage());
    if (!m_language.apply(language))
        out.note(
            QStringLiteral("The %1 translation is missing; messages stay in English.").arg(CliLanguage::id(language)));
    if (!chosen) {
        out.failure(
            QString(), int(CliExit::Usage),
            {ErrorCode::InvalidArgument,
             tr("Unknown language \"%1\" for --lang. Languages: en, zh_CN, system (the locale's).").arg(*lang)});
        return false;
    }
    return true;
}

std::optional<CliExit> Cli::answerWithoutCommand(const CliInvocation &inv, CliOutput &out)
{
    if (inv.has(QStringLiteral("version"))) {
        out.result({{QStringLiteral("version"), QStringLiteral(DRIVEDESK_VERSION)}},
                   QStringLiteral("drivedesk-cli %1").arg(QStringLiteral(DRIVEDESK_VERSION)));
        return CliExit::Ok;
    }
    if (inv.has(QStringLiteral("help"))) {
        QTextStream(stdout) << (inv.command.isEmpty() ? CliHelp::general() : CliHelp::command(inv.command));
        return CliExit::Ok;
    }
    if (inv.command.isEmpty()) {
        out.failure(QString(), int(CliExit::Usage), {ErrorCode::InvalidArgument, tr("No command given.")});
        out.note(tr("Try: drivedesk-cli --help"));
        return CliExit::Usage;
    }
    return std::nullopt;
}

std::optional<CliExit> Cli::loadDictionary(CliContext &context, const QString &command)
{
    CliOutput &out = *context.out;
    auto dictionary = std::make_shared<ParameterDictionary>();
    const Family family = context.globals.connection.family;
    const bool simulatorDictionary = context.globals.dictionaryFile == QLatin1String("simulator")
        || (context.globals.sim && context.globals.dictionaryFile.isEmpty());
    if (simulatorDictionary) {
        *dictionary = ParameterDictionary::bundledSimulator(family);
    } else if (!context.globals.dictionaryFile.isEmpty()) {
        if (Error e = dictionary->loadFromFile(context.globals.dictionaryFile, family)) {
            out.failure(command, int(CliExit::Usage), e);
            return CliExit::Usage;
        }
    } else if (Error e = dictionary->loadForFamily(family)) {
        if (dictionary->isEmpty()) {
            out.failure(command, int(CliExit::DriveFailed), e);
            return CliExit::DriveFailed;
        }
        out.note(tr("Your own %1 dictionary was not used: %2").arg(familyId(family), e.message));
    }
    context.dictionary = dictionary;
    return std::nullopt;
}

Error Cli::startBench(SimBench *bench, CliGlobals *globals)
{
    ConnectionSettings &c = globals->connection;
    SimBenchOptions o;
    o.family = c.family;
    o.baud = c.baud;
    o.bitrate = c.bitrate;
    o.framing = c.framing;
    o.stateFile = globals->simStateFile;
    o.demoMotion = globals->simMotion;
    o.resonanceHz = globals->simResonanceHz;
    if (globals->isCanLink())
        o.can = QStringLiteral("virtualcan:auto"); // a private hub: nobody else on this bus
    if (globals->simDrives.isEmpty())
        o.addresses = {globals->address};
    for (const CliGlobals::SimDrive &d : std::as_const(globals->simDrives)) {
        o.addresses << d.address;
        if (d.baud)
            o.bauds.insert(d.address, d.baud);
    }
    if (Error e = bench->start(o))
        return {e.code == ErrorCode::InvalidArgument ? e.code : ErrorCode::OpenFailed,
                tr("Could not start the simulator: %1").arg(e.message)};
    const ConnectionSettings client = bench->clientSettings();
    c.port = client.port;
    c.can = client.can;
    QStringList drives;
    for (int a : std::as_const(o.addresses))
        drives << (o.bauds.contains(a) ? QStringLiteral("%1@%2").arg(a).arg(o.bauds.value(a)) : QString::number(a));
    globals->simDescription = tr("simulated %1 drives %2 on %3")
                                  .arg(familyId(c.family), drives.join(QLatin1Char(',')), c.linkName());
    return {};
}

int Cli::runCommand(CliCommand *command, CliContext &context)
{
    CliOutput &out = *context.out;
    DriveConnection connection;
    if (context.globals.trace)
        connect(connection.tap(), &TrafficTap::frameRecorded, this, [&out](const TrafficRecord &r) { out.trace(r); });
    configureLogging(false);

    SimBench bench;
    if (context.globals.sim && command->needsLink()) {
        configureLogging(true);
        if (Error e = startBench(&bench, &context.globals)) {
            const CliExit code = e.code == ErrorCode::InvalidArgument ? CliExit::Usage : CliExit::OpenFailed;
            out.failure(command->name(), int(code), e);
            return int(code);
        }
    }

    if (command->needsLink()) {
        Error e;
        if (!connection.open(context.globals.connection, &e)) {
            if (e.message.isEmpty())
                e.message = tr("Could not open %1.").arg(context.globals.connection.linkName());
            const CliExit code = e.code == ErrorCode::OpenFailed || e.code == ErrorCode::LinkClosed
                ? CliExit::OpenFailed
                : e.code == ErrorCode::InvalidArgument ? CliExit::Usage
                                                       : CliExit::DriveFailed;
            out.failure(command->name(), int(code), e);
            return int(code);
        }
        if (context.globals.sim)
            out.note(context.globals.simDescription);
        context.connection = &connection;
        connect(&connection, &DriveConnection::linkLost, command, &CliCommand::linkLost);
        if (command->needsDrive() && !context.drive()) {
            out.failure(command->name(), int(CliExit::Usage),
                        {ErrorCode::InvalidArgument,
                         tr("There can be no %1 drive at address %2 on this link.")
                             .arg(familyId(context.globals.connection.family))
                             .arg(context.globals.address)});
            return int(CliExit::Usage);
        }
    }

    SignalWatcher watcher;
    connect(&watcher, &SignalWatcher::interrupted, command, &CliCommand::interrupt);

    QEventLoop loop;
    connect(command, &CliCommand::done, &loop, &QEventLoop::exit);
    QTimer::singleShot(0, command, &CliCommand::begin);
    const int code = loop.exec();

    context.connection = nullptr;
    connection.close();
    return code;
}

} // namespace dd
