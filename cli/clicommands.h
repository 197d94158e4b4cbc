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
    // The same, choosing the several-drive form of backup and restore (--all, --address
    // 1,2,5) and the two-source form of diff (diff A B).
    static CliCommand *create(const CliInvocation &inv, CliContext *context);
    // Whether the invocation may run without a link (a diff of files and defaults only).
    static bool worksWithoutLink(const CliInvocation &inv);
    // Whether the command needs a QGuiApplication (report: fonts and the PDF writer).
    static bool needsGui(const QString &name);
};

} // namespace dd
