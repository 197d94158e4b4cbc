#include "core/tuning/runparameterapply.h"

#include "core/drive/drive.h"
#include "core/drive/parametertransfer.h"
#include "core/params/parameterdictionary.h"
#include "core/tuning/runcompatibility.h"
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

Error RunParameterApply::check(const TuningRun &run, Family family, const ParameterDictionary &dict,
                               const QVector<TuningEntry> *roles)
{
    if (run.tuning.isEmpty())
        return {ErrorCode::InvalidArgument, tr("The run holds no tuning parameters to apply.")};
    if (familyFromId(run.family) != family)
        return {ErrorCode::InvalidArgument,
                tr("The run was taken on a %1 drive; this drive is %2.").arg(run.family, familyId(family))};
    if (const QStringList twice = RunCompatibility::snapshotProblems(run); !twice.isEmpty())
        return {ErrorCode::InvalidArgument,
                twice.join(QLatin1Char(' ')) + QLatin1Char(' ') + tr("The whole run is refused; nothing was written.")};
    const QVector<TuningEntry> &inForce = roles ? *roles : dict.tuning();
    auto roleInForce = [&inForce](int index) {
        for (const TuningEntry &t : inForce)
            if (t.index == index)
                return t.role;
        return QString();
    };
    const QString dictName = dict.sourceName().isEmpty() ? familyId(family) : dict.sourceName();
    if (inForce.isEmpty()) {
        QStringList recorded;
        for (const TuningSnapshotEntry &e : run.tuning)
            if (!e.role.isEmpty())
                recorded << QStringLiteral("%1 = %2").arg(e.key, e.role);
        QString message = tr("The drive's dictionary (%1) names no tuning parameters, so nothing tells a loop gain "
                             "from a setting: apply-run writes only parameters whose role in the drive's dictionary "
                             "is a tuning role.")
                              .arg(dictName);
        if (!recorded.isEmpty())
            message += QLatin1Char(' ')
                + tr("The run was recorded with a dictionary that gives them roles (%1): DriveDesk's simulator "
                     "names its own loop gains so, which mean something else, or nothing, on a real drive.")
                      .arg(recorded.join(QStringLiteral(", ")));
        return {ErrorCode::InvalidArgument, message + QLatin1Char(' ') + tr("Nothing was written.")};
    }
    QStringList notTuning;
    for (const TuningSnapshotEntry &e : run.tuning) {
        const ParameterInfo *p = dict.byIndex(e.index);
        if (!p || p->key.compare(e.key, Qt::CaseInsensitive) != 0)
            return {ErrorCode::InvalidArgument,
                    tr("The run's parameter %1 (index %2) is not that parameter in the drive's dictionary.")
                        .arg(e.key)
                        .arg(e.index)};
        const QString role = roleInForce(e.index);
        if (role.isEmpty()) {
            notTuning << dict.label(e.index);
            continue;
        }
        if (!e.role.isEmpty() && e.role != role)
            return {ErrorCode::InvalidArgument,
                    tr("The run's %1 has the role %2; in the drive's dictionary (%3) it is %4: the run was recorded "
                       "with another dictionary. Nothing was written.")
                        .arg(e.key, e.role, dictName, role)};
    }
    if (!notTuning.isEmpty())
        return {ErrorCode::InvalidArgument,
                tr("The run lists parameters that are not tuning parameters in the drive's dictionary (%1): %2. "
                   "apply-run writes only tuning parameters; the whole run is refused and nothing was written.")
                    .arg(dictName, notTuning.join(QStringLiteral(", ")))};
    for (const TuningSnapshotEntry &e : run.tuning) {
        if (Error err = dict.validateWrite(e.index, e.value)) {
            err.message = tr("The run's %1 = %2 cannot be applied: %3").arg(e.key).arg(e.value).arg(err.message);
            return err;
        }
    }
    return {};
}

Error RunParameterApply::checkDrive(const TuningRun &run, const DriveIdentity &identity)
{
    const QString runModel = run.model.trimmed(), driveModel = identity.model.trimmed();
    if (!runModel.isEmpty() && !driveModel.isEmpty() && runModel.compare(driveModel, Qt::CaseInsensitive) != 0)
        return {ErrorCode::InvalidArgument,
                tr("The run was taken on a %1; this drive is a %2. Tuning values do not carry over between models; "
                   "nothing was written.")
                    .arg(runModel, driveModel)};
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

Error RunParameterApply::apply(const TuningRun &run, bool dryRun, bool force, const QVector<TuningEntry> *roles)
{
    if (!m_drive)
        return {ErrorCode::LinkClosed, tr("The drive is gone.")};
    if (m_transfer->isRunning())
        return {ErrorCode::Busy, tr("A backup or restore is already running on this drive.")};
    if (Error e = check(run, m_drive->family(), m_drive->parameterDictionary(), roles))
        return e;
    if (Error e = checkDrive(run, m_drive->identity()))
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
