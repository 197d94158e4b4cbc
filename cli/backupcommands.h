#pragma once

#include "cli/clicommand.h"

#include "core/drive/restorereport.h"
#include "core/params/backupfile.h"

// Backup commands: backup -o FILE, diff FILE, restore FILE [--dry-run] [--only ...] [--force].
// The workflow itself is dd::ParameterTransfer (core), shared with the GUI.

namespace dd {

class ParameterTransfer;

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

private:
    QString m_path;
    ParameterTransfer *m_transfer = nullptr;
};

// diff and restore: both load and check the file completely before the link is opened.
class FileCommand : public CliCommand
{
    Q_OBJECT
public:
    using CliCommand::CliCommand;
    bool prepare(const CliInvocation &inv, QString *error) override;

protected:
    QJsonArray diffJson() const;
    QString diffText(bool onlyDifferences) const;
    QString m_path;
    BackupFile m_file;
    ParameterTransfer *m_transfer = nullptr;
};

class DiffCommand : public FileCommand
{
    Q_OBJECT
public:
    explicit DiffCommand(CliContext *c)
        : FileCommand(QStringLiteral("diff"), c)
    {
    }
    void start() override;
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
    void start() override;
    // Writes in flight finish and are verified; the report tells what was done.
    void interrupt(int) override;

private:
    void report(const Error &error);
    // What became of the parameter's write (also into its JSON object `o`).
    QString outcome(int index, QJsonObject *o) const;
    QJsonObject reportJson(const QJsonArray &selected) const;
    // After a failure: what was written and what was not.
    void printIncomplete(const QList<QPair<QString, QString>> &rows);
    RestoreOptions m_options;
};

} // namespace dd
