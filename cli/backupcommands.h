#pragma once

#include "cli/clicommand.h"

#include "core/drive/restorereport.h"
#include "core/params/backupfile.h"

// Backup commands: backup -o FILE, diff FILE, restore FILE [--dry-run] [--only ...] [--force].
// The workflow itself is dd::ParameterTransfer (core), shared with the GUI.

namespace dd {

class ParameterDictionary;
class ParameterTransfer;
struct ConnectionSettings;

class BackupCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit BackupCommand(CliContext *c)
        : CliCommand(QStringLiteral("backup"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;
    // The link settings into the file; with changedOnly only the values changed from the
    // dictionary's defaults, the file marked so.
    static void complete(BackupFile *file, const ConnectionSettings &c, const ParameterDictionary &dict,
                         bool changedOnly);

private:
    QString m_path;
    bool m_changedOnly = false;
    ParameterTransfer *m_transfer = nullptr;
};

// diff and restore: both load and check the file completely before the link is opened.
class FileCommand : public CliCommand
{
    Q_OBJECT
public:
    using CliCommand::CliCommand;
    bool prepare(const CliInvocation &inv, QString *error) override;
    // Loads and checks a backup file completely (also its family against the link's).
    static bool loadFile(const CliContext *context, const QString &path, BackupFile *file, QString *error);

protected:
    QJsonArray diffJson() const;
    QString diffText(bool onlyDifferences) const;
    QString m_path;
    BackupFile m_file;
    ParameterTransfer *m_transfer = nullptr;
};

// diff's exit code, like diff(1): 0 equal, 1 different, 2 trouble (bad input, or a drive
// that did not answer), 3 the port could not be opened.
CliExit diffExitForFailure(const Error &error);

class DiffCommand : public FileCommand
{
    Q_OBJECT
public:
    explicit DiffCommand(CliContext *c)
        : FileCommand(QStringLiteral("diff"), c)
    {
    }
    void start() override;

protected:
    CliExit exitForFailure(const Error &error) const override { return diffExitForFailure(error); }
};

class RestoreCommand : public FileCommand
{
    Q_OBJECT
public:
    explicit RestoreCommand(CliContext *c)
        : FileCommand(QStringLiteral("restore"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    // --dry-run, --force, --only (checked against the file and the dictionary).
    static bool parseOptions(const CliInvocation &inv, const BackupFile &file, const QString &path,
                             const ParameterDictionary &dict, RestoreOptions *options, QString *error);
    void start() override;
    // Writes in flight finish and are verified; the report tells what was done.
    void interrupt(int) override;

private:
    void report(const Error &error);
    RestoreOptions m_options;
};

} // namespace dd
