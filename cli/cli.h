#pragma once

#include "cli/clilanguage.h"
#include "core/common/error.h"

#include <QObject>
#include <QStringList>

namespace dd {

class SimBench;
struct CliGlobals;
class CliCommand;
class CliOutput;
struct CliContext;

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
    // simulator also virtualcan's expected warnings about its private hub.
    static void configureLogging(bool sim);

private:
    // --sim: simulated drives in this process; points the connection settings at them.
    static Error startBench(SimBench *bench, CliGlobals *globals);
    int runCommand(CliCommand *command, CliContext &context);

    CliLanguage m_language;
};

} // namespace dd
