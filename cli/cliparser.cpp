#include "cli/cliparser.h"

namespace dd {

namespace {

bool looksLikeNumber(const QString &arg)
{
    // "-100", "-0.5", "-.5": a negative value, not an option.
    return arg.size() > 1 && arg.at(0) == QLatin1Char('-')
        && (arg.at(1).isDigit() || arg.at(1) == QLatin1Char('.'));
}

} // namespace

CliParser::CliParser(QList<CliOptionSpec> globals, QList<CliCommandSpec> commands)
    : m_globals(std::move(globals))
    , m_commands(std::move(commands))
{
}

bool CliParser::isCommand(const QString &name) const
{
    return findCommand(name) != nullptr;
}

QStringList CliParser::commandNames() const
{
    QStringList names;
    for (const CliCommandSpec &c : m_commands)
        names << c.name;
    return names;
}

const CliCommandSpec *CliParser::findCommand(const QString &name) const
{
    for (const CliCommandSpec &c : m_commands)
        if (c.name == name)
            return &c;
    return nullptr;
}

const CliOptionSpec *CliParser::findLong(const QList<CliOptionSpec> &specs, const QString &name) const
{
    for (const CliOptionSpec &s : specs)
        if (s.name == name)
            return &s;
    return nullptr;
}

const CliOptionSpec *CliParser::findShort(const QList<CliOptionSpec> &specs, QChar c) const
{
    for (const CliOptionSpec &s : specs)
        if (!s.shortName.isNull() && s.shortName == c)
            return &s;
    return nullptr;
}

bool CliParser::parse(const QStringList &arguments, CliInvocation *out, QString *error) const
{
    *out = {};
    const CliCommandSpec *command = nullptr;
    bool optionsEnded = false;

    for (int i = 0; i < arguments.size(); ++i) {
        const QString arg = arguments.at(i);
        const bool isOption = !optionsEnded && arg.startsWith(QLatin1Char('-')) && arg.size() > 1
            && !looksLikeNumber(arg);
        if (!isOption) {
            if (arg == QLatin1String("--") && !optionsEnded) {
                optionsEnded = true;
                continue;
            }
            if (!command) {
                command = findCommand(arg);
                if (!command) {
                    *error = tr("Unknown command \"%1\". Commands: %2.")
                                 .arg(arg, commandNames().join(QLatin1String(", ")));
                    return false;
                }
                out->command = command->name;
            } else {
                out->positionals << arg;
            }
            continue;
        }
        if (arg == QLatin1String("--")) {
            optionsEnded = true;
            continue;
        }

        const CliOptionSpec *spec = nullptr;
        QString shown;
        QString inlineValue;
        bool hasInlineValue = false;
        if (arg.startsWith(QLatin1String("--"))) {
            QString name = arg.mid(2);
            const int eq = name.indexOf(QLatin1Char('='));
            if (eq >= 0) {
                inlineValue = name.mid(eq + 1);
                hasInlineValue = true;
                name.truncate(eq);
            }
            shown = QLatin1String("--") + name;
            spec = findLong(m_globals, name);
            if (!spec && command)
                spec = findLong(command->options, name);
        } else {
            shown = arg.left(2);
            spec = findShort(m_globals, arg.at(1));
            if (!spec && command)
                spec = findShort(command->options, arg.at(1));
            if (spec && arg.size() > 2) {
                inlineValue = arg.mid(2);  // -oFILE
                hasInlineValue = true;
            }
        }
        if (!spec) {
            if (command)
                *error = tr("Unknown option %1 for \"%2\". See: drivedesk-cli %2 --help")
                             .arg(shown, command->name);
            else
                *error = tr("Unknown option %1. See: drivedesk-cli --help").arg(shown);
            return false;
        }
        if (!spec->takesValue) {
            if (hasInlineValue) {
                *error = tr("Option --%1 takes no value.").arg(spec->name);
                return false;
            }
            out->options.insert(spec->name, QString());
            continue;
        }
        if (!hasInlineValue) {
            if (i + 1 >= arguments.size()) {
                *error = tr("Option --%1 needs a value.").arg(spec->name);
                return false;
            }
            inlineValue = arguments.at(++i);
        }
        out->options.insert(spec->name, inlineValue);
        if (spec->repeatable)
            out->lists[spec->name].append(inlineValue);
    }
    return true;
}

} // namespace dd
