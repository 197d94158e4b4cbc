#pragma once

#include "cli/cliexit.h"
#include "cli/clilanguage.h"
#include "core/common/error.h"

#include <QObject>
#include <QStringList>
#include <optional>

namespace dd {

class SimBench;
struct CliGlobals;
class CliCommand;
class CliOutput;
struct CliContext;
struct CliInvocation;

// The command-line tool: parse, check everything, open the link, run one command, return
// its exit code (see CliExit).
class Cli : public QObject
{
    Q_OBJECT
public:
    explicit Cli(QObject *parent = nullptr);
    ~Cli() override;

    // `arguments` without the program name. Runs an event loop until the command is done.
    int run(const QStringList &arguments);

    // stderr is for the CLI's own messages and --trace: the libraries' debug and info
    // chatter stays off (QT_LOGGING_RULES in the environment still overrides this); with the
    // simulator also virtualcan's expected warnings about its private hub. (Stray or late
    // frames are the link's to handle; --trace shows them as discarded frames.)
    static void configureLogging(bool sim);
    // Whether the command line asks for a command that needs a QGuiApplication (report); main()
    // then makes one on the offscreen platform, so that no display is needed.
    static bool needsGuiApplication(const QStringList &arguments);

private:
    // Speaks the language of --lang (English with --json); false after saying that --lang
    // names no language.
    bool applyLanguage(const QStringList &arguments, bool json, CliOutput &out);
    // --version, --help, or no command: the exit code once answered; nothing otherwise.
    static std::optional<CliExit> answerWithoutCommand(const CliInvocation &inv, CliOutput &out);
    // The parameter dictionary into `context`: the exit code if there is none to use.
    static std::optional<CliExit> loadDictionary(CliContext &context, const QString &command);
    // --sim: simulated drives in this process; points the connection settings at them.
    static Error startBench(SimBench *bench, CliGlobals *globals);
    int runCommand(CliCommand *command, CliContext &context);

    CliLanguage m_language;
};

} // namespace dd
