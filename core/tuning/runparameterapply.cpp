#include "core/tuning/runparameterapply.h"

#include "core/drive/drive.h"
#include "core/drive/parametertransfer.h"
#include "core/params/parameterdictionary.h"
#include "core/tuning/tuningrun.h"

namespace dd {

RunParameterApply::RunParameterApply(Drive *drive, QObject *parent)
    : QObject(parent)
    , m_drive(drive)
    , m_transfer(new ParameterTransfer(drive, this))
{
    connect(m_transfer, &ParameterTransfer::progress, this, &RunParameterApply::progress);
    connect(m_transfer, &ParameterTransfer::finished, this, &RunParameterApply::finished);
}

RunParameterApply::~RunParameterApply() = default;

Error RunParameterApply::check(const TuningRun &run, Family family, const ParameterDictionary &dict)
{
    if (run.tuning.isEmpty())
        return {ErrorCode::InvalidArgument, tr("The run holds no tuning parameters to apply.")};
    if (familyFromId(run.family) != family)
        return {ErrorCode::InvalidArgument,
                tr("The run was taken on a %1 drive; this drive is %2.").arg(run.family, familyId(family))};
    for (const TuningSnapshotEntry &e : run.tuning) {
        const ParameterInfo *p = dict.byIndex(e.index);
        if (!p || p->key.compare(e.key, Qt::CaseInsensitive) != 0)
            return {ErrorCode::InvalidArgument,
                    tr("The run's parameter %1 (index %2) is not that parameter in the drive's dictionary.")
                        .arg(e.key)
                        .arg(e.index)};
        if (Error err = dict.validateWrite(e.index, e.value)) {
            err.message = tr("The run's %1 = %2 cannot be applied: %3").arg(e.key).arg(e.value).arg(err.message);
            return err;
        }
    }
    return {};
}

BackupFile RunParameterApply::snapshotFile(const TuningRun &run)
{
    BackupFile file;
    if (const auto f = familyFromId(run.family))
        file.setFamily(*f);
    file.setAddress(run.address);
    file.setFirmware(run.firmware);
    file.setModel(run.model);
    ParameterSet values;
    for (const TuningSnapshotEntry &e : run.tuning)
        values.set(e.index, e.value, ValueSource::ReadFromDrive);
    file.setValues(values);
    return file;
}

Error RunParameterApply::apply(const TuningRun &run, bool dryRun, bool force)
{
    if (!m_drive)
        return {ErrorCode::LinkClosed, tr("The drive is gone.")};
    if (m_transfer->isRunning())
        return {ErrorCode::Busy, tr("A backup or restore is already running on this drive.")};
    if (Error e = check(run, m_drive->family(), m_drive->parameterDictionary()))
        return e;
    m_file = snapshotFile(run);
    RestoreOptions options;
    options.dryRun = dryRun;
    options.force = force;
    for (const TuningSnapshotEntry &e : run.tuning)
        options.only << e.index;
    m_transfer->restore(m_file, options);
    return {};
}

bool RunParameterApply::isRunning() const
{
    return m_transfer->isRunning();
}

const RestoreReport &RunParameterApply::report() const
{
    return m_transfer->report();
}

const ParameterDictionary &RunParameterApply::dictionary() const
{
    return m_transfer->dictionary();
}

} // namespace dd
