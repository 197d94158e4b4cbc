#include "core/params/parameterdiff.h"

#include "core/params/parameterdictionary.h"

namespace dd {

QString diffStatusId(DiffStatus status)
{
    switch (status) {
    case DiffStatus::Same: return QStringLiteral("same");
    case DiffStatus::Different: return QStringLiteral("different");
    case DiffStatus::OnlyInFile: return QStringLiteral("only-in-file");
    case DiffStatus::OnlyOnDrive: return QStringLiteral("only-on-drive");
    case DiffStatus::NotReadable: return QStringLiteral("not-readable");
    }
    return {};
}

ParameterDiff ParameterDiff::compute(const ParameterDictionary &dictionary, const ParameterSet &file,
                                     const ParameterSet &drive)
{
    ParameterDiff diff;
    for (const ParameterInfo &p : dictionary.parameters()) {
        const std::optional<qint64> inFile = file.value(p.index);
        const std::optional<qint64> onDrive = drive.value(p.index);
        if (!inFile && !onDrive)
            continue;
        DiffEntry e;
        e.index = p.index;
        e.key = p.key;
        e.fileValue = inFile;
        e.driveValue = onDrive;
        e.access = p.access;
        e.communication = p.communication;
        if (!inFile)
            e.status = DiffStatus::OnlyOnDrive;
        else if (p.access == Access::WriteOnly)
            e.status = DiffStatus::NotReadable;
        else if (!onDrive)
            e.status = DiffStatus::OnlyInFile;
        else
            e.status = *inFile == *onDrive ? DiffStatus::Same : DiffStatus::Different;
        diff.m_entries.append(e);
    }
    return diff;
}

const DiffEntry *ParameterDiff::entry(int index) const
{
    for (const DiffEntry &e : m_entries) {
        if (e.index == index)
            return &e;
    }
    return nullptr;
}

int ParameterDiff::count(DiffStatus status) const
{
    int n = 0;
    for (const DiffEntry &e : m_entries)
        n += e.status == status ? 1 : 0;
    return n;
}

static bool wouldWrite(const DiffEntry &e)
{
    return e.fileValue && e.access != Access::ReadOnly
        && (e.status == DiffStatus::Different || e.status == DiffStatus::OnlyInFile
            || e.status == DiffStatus::NotReadable);
}

bool ParameterDiff::hasDifferences() const
{
    for (const DiffEntry &e : m_entries) {
        if (wouldWrite(e) && !e.communication)
            return true;
    }
    return false;
}

Error ParameterDiff::selectForWrite(const QList<int> &only, QVector<DiffEntry> *out) const
{
    for (int index : only) {
        const DiffEntry *e = entry(index);
        if (!e || !e->fileValue) {
            return Error{ErrorCode::InvalidArgument,
                         tr("Parameter %1 has no value in the backup file, so it cannot be restored")
                             .arg(e ? e->key : QString::number(index))};
        }
        if (e->access == Access::ReadOnly) {
            return Error{ErrorCode::NotSupported,
                         tr("Parameter %1 is read-only, so it cannot be restored").arg(e->key)};
        }
    }
    QVector<DiffEntry> selected;
    for (const DiffEntry &e : m_entries) {
        if (!wouldWrite(e))
            continue;
        const bool named = only.contains(e.index);
        if (!only.isEmpty() && !named)
            continue;
        if (e.communication && !named)
            continue;
        selected.append(e);
    }
    *out = selected;
    return Error::none();
}

} // namespace dd
