#pragma once

#include "cli/cliparser.h"

namespace dd {

class CliCommand;
struct CliContext;

// The table of commands: their options (for the parser) and their classes.
class CliCommands
{
public:
    static QList<CliCommandSpec> specs();
    // The command object for a name from specs() (never nullptr for those).
    static CliCommand *create(const QString &name, CliContext *context);
};

} // namespace dd
