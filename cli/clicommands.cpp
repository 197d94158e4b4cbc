#include "cli/clicommands.h"

#include "cli/backupcommands.h"
#include "cli/capturecommand.h"
#include "cli/drivecommands.h"
#include "cli/eecommand.h"
#include "cli/fleetbackupcommand.h"
#include "cli/fleetrestorecommand.h"
#include "cli/monitorcommand.h"
#include "cli/motioncommands.h"
#include "cli/paramcommands.h"
#include "cli/pingcommand.h"
#include "cli/reportcommand.h"
#include "cli/runcommands.h"
#include "cli/scancommand.h"
#include "cli/sourcediffcommand.h"
#include "cli/stepcommand.h"

#include <QFileInfo>

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
        {QStringLiteral("backup"),
         {valued("output", QLatin1Char('o')), flag("changed-only"), flag("all"), valued("from"), valued("to")}},
        {QStringLiteral("diff"), {}},
        {QStringLiteral("restore"),
         {flag("dry-run"), valued("only"), flag("force"), flag("all"), valued("from"), valued("to"),
          flag("stop-on-failure")}},
        {QStringLiteral("ee"), {}},
        {QStringLiteral("monitor"), {valued("rate"), valued("duration"), valued("output", QLatin1Char('o'))}},
        {QStringLiteral("jog"), {valued("duration"), flag("enable")}},
        {QStringLiteral("move"), {valued("by"), valued("to"), valued("speed"), flag("no-wait"), flag("enable")}},
        {QStringLiteral("stop"), {flag("emergency")}},
        {QStringLiteral("enable"), {}},
        {QStringLiteral("clear-alarm"), {}},
        {QStringLiteral("home"), {flag("positive"), flag("no-wait")}},
        {QStringLiteral("channels"), {}},
        {QStringLiteral("ping"), {valued("count")}},
        {QStringLiteral("capture"),
         {valued("trigger"), valued("pre"), valued("duration"), valued("mode"), valued("timeout"), valued("notes"),
          valued("output", QLatin1Char('o'))}},
        {QStringLiteral("step"),
         {valued("duration"), valued("speed"), valued("max-speed"), valued("max-travel"), valued("max-duration"),
          valued("record"), valued("pre"), valued("channels"), flag("no-return"), valued("notes"),
          valued("counts-per-rev"), flag("enable"), valued("output", QLatin1Char('o'))}},
        {QStringLiteral("runs"), {}},
        {QStringLiteral("apply-run"), {flag("dry-run"), flag("force")}},
        {QStringLiteral("spectrum"), {valued("peaks"), valued("from"), valued("between")}},
        {QStringLiteral("report"),
         {valued("output", QLatin1Char('o')), flag("all"), valued("from"), valued("to"), valued("runs"),
          valued("header"), valued("json-out"), valued("page-size")}},
    };
}

bool CliCommands::worksWithoutLink(const CliInvocation &inv)
{
    return inv.command == QLatin1String("diff") && inv.positionals.size() == 2
        && !SourceDiffCommand::namesADrive(inv.positionals);
}

CliCommand *CliCommands::create(const CliInvocation &inv, CliContext *context)
{
    const bool many = inv.has(QStringLiteral("all")) || context->globals.addresses.size() > 1;
    if (inv.command == QLatin1String("backup") && many)
        return new FleetBackupCommand(context);
    const bool folder = !inv.positionals.isEmpty() && QFileInfo(inv.positionals.first()).isDir();
    if (inv.command == QLatin1String("restore") && (many || folder))
        return new FleetRestoreCommand(context);
    if (inv.command == QLatin1String("diff") && inv.positionals.size() >= 2)
        return new SourceDiffCommand(context);
    return create(inv.command, context);
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
    if (name == QLatin1String("ping"))
        return new PingCommand(context);
    if (name == QLatin1String("capture"))
        return new CaptureCommand(context);
    if (name == QLatin1String("step"))
        return new StepCommand(context);
    if (name == QLatin1String("runs"))
        return new RunsCommand(context);
    if (name == QLatin1String("apply-run"))
        return new ApplyRunCommand(context);
    if (name == QLatin1String("spectrum"))
        return new SpectrumCommand(context);
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
