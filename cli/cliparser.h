#pragma once

#include <QCoreApplication>
#include <QHash>
#include <QList>
#include <QString>
#include <QStringList>

namespace dd {

// One option: `--name VALUE` / `--name=VALUE` when it takes a value, `--name` otherwise;
// optionally a one-letter form (`-o FILE`).
struct CliOptionSpec
{
    QString name;
    bool takesValue = false;
    QChar shortName;
    bool repeatable = false; // every value is kept (CliInvocation::values)
};

// A command and the options it accepts besides the global ones.
struct CliCommandSpec
{
    QString name;
    QList<CliOptionSpec> options;
};

// What the command line says, before any value is interpreted.
struct CliInvocation
{
    QString command;
    QStringList positionals;           // the command's arguments, in order
    QHash<QString, QString> options;   // long name → value ("" for flags); last one wins
    QHash<QString, QStringList> lists; // repeatable options: every value, in order

    bool has(const QString &name) const { return options.contains(name); }
    QString value(const QString &name) const { return options.value(name); }
    QStringList values(const QString &name) const { return lists.value(name); }
};

// Splits argv into global options, the command, its options and its arguments. Global
// options may stand before or after the command; a command's options only after it.
// "--" ends option processing; an argument such as "-100" is a (negative) number, not an
// option. Knows nothing of what the values mean.
class CliParser
{
    Q_DECLARE_TR_FUNCTIONS(dd::Cli)
public:
    CliParser(QList<CliOptionSpec> globals, QList<CliCommandSpec> commands);

    // false with a translated message in *error when the command line is malformed.
    bool parse(const QStringList &arguments, CliInvocation *out, QString *error) const;

    bool isCommand(const QString &name) const;
    QStringList commandNames() const;

private:
    // An option word: its spec, and the value written into it (--name=VALUE, -oVALUE).
    struct OptionWord
    {
        const CliOptionSpec *spec = nullptr;
        QString inlineValue;
        bool hasInlineValue = false;
    };

    // A word that is not an option: the command, or (after it) one of its arguments.
    bool takeWord(const QString &arg, const CliCommandSpec **command, CliInvocation *out, QString *error) const;
    // Finds the option `arg` names (a global one, or one of `command`'s).
    bool readOption(const QString &arg, const CliCommandSpec *command, OptionWord *word, QString *error) const;
    const CliOptionSpec *findLong(const QList<CliOptionSpec> &specs, const QString &name) const;
    const CliOptionSpec *findShort(const QList<CliOptionSpec> &specs, QChar c) const;
    const CliCommandSpec *findCommand(const QString &name) const;

    QList<CliOptionSpec> m_globals;
    QList<CliCommandSpec> m_commands;
};

} // namespace dd
