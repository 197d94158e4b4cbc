#include "cli/clicommands.h"

#include "cli/backupcommands.h"
#include "cli/drivecommands.h"
#include "cli/eecommand.h"
#include "cli/monitorcommand.h"
#include "cli/motioncommands.h"
#include "cli/paramcommands.h"
#include "cli/reportcommand.h"
#include "cli/scancommand.h"

namespace dd {

namespace {

CliOptionSpec flag(const char *name)
{
    return {QLatin1String(name), false, {}};
}
CliOptionSpec valued(const char *name, QChar shortName = {})
{
    return {QLatin1String(name), true, shortName};
}

} // namespace

bool CliCommands::needsGui(const QString &name)
{
    return name == QLatin1String("report"); // fonts and QPdfWriter
}

QList<CliCommandSpec> CliCommands::specs()
{
    return {
        {QStringLiteral("scan"), {valued("from"), valued("to"), valued("bauds")}},
        {QStringLiteral("info"), {}},
        {QStringLiteral("get"), {}},
        {QStringLiteral("set"), {}},
        {QStringLiteral("backup"), {valued("output", QLatin1Char('o'))}},
        {QStringLiteral("diff"), {}},
        {QStringLiteral("restore"), {flag("dry-run"), valued("only"), flag("force")}},
        {QStringLiteral("ee"), {}},
        {QStringLiteral("monitor"), {valued("rate"), valued("duration"), valued("output", QLatin1Char('o'))}},
        {QStringLiteral("jog"), {valued("duration")}},
        {QStringLiteral("move"), {valued("by"), valued("to"), valued("speed"), flag("no-wait")}},
        {QStringLiteral("stop"), {flag("emergency")}},
        {QStringLiteral("enable"), {}},
        {QStringLiteral("clear-alarm"), {}},
        {QStringLiteral("home"), {flag("positive"), flag("no-wait")}},
        {QStringLiteral("channels"), {}},
        {QStringLiteral("report"),
         {valued("output", QLatin1Char('o')), flag("all"), valued("from"), valued("to"), valued("runs"),
          valued("header"), valued("json-out"), valued("page-size")}},
    };
}

CliCommand *CliCommands::create(const QString &name, CliContext *context)
{
    if (name == QLatin1String("scan"))
        return new ScanCommand(context);
    if (name == QLatin1String("ee"))
        return new EeCommand(context);
    if (name == QLatin1String("monitor"))
        return new MonitorCommand(context);
    if (name == QLatin1String("jog"))
        return new JogCommand(context);
    if (name == QLatin1String("move"))
        return new MoveCommand(context);
    if (name == QLatin1String("home"))
        return new HomeCommand(context);
    if (name == QLatin1String("get"))
        return new GetCommand(context);
    if (name == QLatin1String("set"))
        return new SetCommand(context);
    if (name == QLatin1String("backup"))
        return new BackupCommand(context);
    if (name == QLatin1String("diff"))
        return new DiffCommand(context);
    if (name == QLatin1String("restore"))
        return new RestoreCommand(context);
    if (name == QLatin1String("info"))
        return new InfoCommand(context);
    if (name == QLatin1String("channels"))
        return new ChannelsCommand(context);
    if (name == QLatin1String("stop"))
        return new StopCommand(context);
    if (name == QLatin1String("enable"))
        return new EnableCommand(context);
    if (name == QLatin1String("clear-alarm"))
        return new ClearAlarmCommand(context);
    if (name == QLatin1String("report"))
        return new ReportCommand(context);
    Q_UNREACHABLE();
    return nullptr;
}

} // namespace dd
