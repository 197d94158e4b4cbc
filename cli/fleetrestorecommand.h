#pragma once

#include "cli/fleetcommand.h"

#include "core/drive/restorereport.h"
#include "core/params/backupfile.h"

namespace dd {

// restore FILE --all / restore FILE --address 1,2,5: the same file to every drive, each at
// its own address; per drive only the differences are written and each is read back.
// Communication settings (address, baud, station number) are left alone unless --only names
// them. --stop-on-failure: one drive after the other, none after the first that fails.
// restore DIR [--address 1,2,5]: a folder written by backup --all -o DIR put back — every
// drive its index.json lists (or those of --address) from its own file, at its address.
class FleetRestoreCommand : public FleetCommand
{
    Q_OBJECT
public:
    explicit FleetRestoreCommand(CliContext *c)
        : FleetCommand(QStringLiteral("restore"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;

protected:
    void run(const QList<int> &addresses) override;

private:
    void report();
    bool prepareFolder(const CliInvocation &inv, QString *error);

    QString m_path;
    BackupFile m_file;
    QVector<BackupFile> m_files; // folder: one per target, in order
    QStringList m_fileNames;
    RestoreOptions m_options;
    bool m_stopOnFailure = false;
};

} // namespace dd
