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
    // Whether the command needs a QGuiApplication (report: fonts and the PDF writer).
    static bool needsGui(const QString &name);
};

} // namespace dd
