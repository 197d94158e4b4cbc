#include "cli/cliparser.h"

namespace dd {

namespace {

bool looksLikeNumber(const QString &arg)
{
    // "-100", "-0.5", "-.5": a negative value, not an option.
    return arg.size() > 1 && arg.at(0) == QLatin1Char('-') && (arg.at(1).isDigit() || arg.at(1) == QLatin1Char('.'));
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
            if (!takeWord(arg, &command, out, error))
                return false;
            continue;
        }
        if (arg == QLatin1String("--")) {
            optionsEnded = true;
            continue;
        }

        OptionWord word;
        if (!readOption(arg, command, &word, error))
            return false;
        if (!word.spec->takesValue) {
            if (word.hasInlineValue) {
                *error = tr("Option --%1 takes no value.").arg(word.spec->name);
                return false;
            }
            out->options.insert(word.spec->name, QString());
            continue;
        }
        if (!word.hasInlineValue) {
            if (i + 1 >= arguments.size()) {
                *error = tr("Option --%1 needs a value.").arg(word.spec->name);
                return false;
            }
            word.inlineValue = arguments.at(++i);
        }
        out->options.insert(word.spec->name, word.inlineValue);
        if (word.spec->repeatable)
            out->lists[word.spec->name].append(word.inlineValue);
    }
    return true;
}

bool CliParser::takeWord(const QString &arg, const CliCommandSpec **command, CliInvocation *out, QString *error) const
{
    if (*command) {
        out->positionals << arg;
        return true;
    }
    *command = findCommand(arg);
    if (!*command) {
        *error = tr("Unknown command \"%1\". Commands: %2.").arg(arg, commandNames().join(QLatin1String(", ")));
        return false;
    }
    out->command = (*command)->name;
    return true;
}

bool CliParser::readOption(const QString &arg, const CliCommandSpec *command, OptionWord *word, QString *error) const
{
    QString shown;
    if (arg.startsWith(QLatin1String("--"))) {
        QString name = arg.mid(2);
        const int eq = name.indexOf(QLatin1Char('='));
        if (eq >= 0) {
            word->inlineValue = name.mid(eq + 1);
            word->hasInlineValue = true;
            name.truncate(eq);
        }
        shown = QLatin1String("--") + name;
        word->spec = findLong(m_globals, name);
        if (!word->spec && command)
            word->spec = findLong(command->options, name);
    } else {
        shown = arg.left(2);
        word->spec = findShort(m_globals, arg.at(1));
        if (!word->spec && command)
            word->spec = findShort(command->options, arg.at(1));
        if (word->spec && arg.size() > 2) {
            word->inlineValue = arg.mid(2); // -oFILE
            word->hasInlineValue = true;
        }
    }
    if (word->spec)
        return true;
    if (command)
        *error = tr("Unknown option %1 for \"%2\". See: drivedesk-cli %2 --help").arg(shown, command->name);
    else
        *error = tr("Unknown option %1. See: drivedesk-cli --help").arg(shown);
    return false;
}

} // namespace dd
