#pragma once

#include "cli/fleetcommand.h"

namespace dd {

// backup --all -o DIR / backup --address 1,2,5 -o DIR: one file per drive, named
// FAMILY-ADDRESS.json, and DIR/index.json listing every drive and its result (a drive that
// failed gets no file; an older file of it stays as it was). --changed-only as for one drive.
class FleetBackupCommand : public FleetCommand
{
    Q_OBJECT
public:
    explicit FleetBackupCommand(CliContext *c)
        : FleetCommand(QStringLiteral("backup"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    static QString indexFormatName(); // "drivedesk-backup-index"

protected:
    void run(const QList<int> &addresses) override;
    CliExit exitOf(const FleetDriveResult &result) const override;

private:
    void save();
    QString fileName(int address) const;

    QString m_dir;
    bool m_changedOnly = false;
    QMap<int, Error> m_saveErrors; // address -> the file could not be written
};

} // namespace dd
