#include "clicommands.h"

#include "drivecommands.h"

namespace dd {

namespace {

CliOptionSpec flag(const char *name) { return {QLatin1String(name), false, {}}; }
CliOptionSpec valued(const char *name, QChar shortName = {}) { return {QLatin1String(name), true, shortName}; }

} // namespace

QList<CliCommandSpec> CliCommands::specs()
{
    return {
        {QStringLiteral("info"), {}},
        {QStringLiteral("channels"), {}},
        {QStringLiteral("stop"), {flag("emergency")}},
        {QStringLiteral("enable"), {}},
        {QStringLiteral("clear-alarm"), {}},
    };
}

CliCommand *CliCommands::create(const QString &name, CliContext *context)
{
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
    Q_UNREACHABLE();
    return nullptr;
}

} // namespace dd
