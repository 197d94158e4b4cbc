#pragma once

#include "core/common/error.h"
#include "core/params/parameterinfo.h"
#include "core/params/parameterset.h"

#include <QCoreApplication>
#include <QList>
#include <QVector>
#include <optional>

namespace dd {

class ParameterDictionary;

enum class DiffStatus {
    Same,        // readable, equal on both sides
    Different,   // readable, values differ
    OnlyInFile,  // readable, the file has a value, the drive's is not known
    OnlyOnDrive, // the drive has a value, the file has none
    NotReadable  // write-only: the file has a value, the drive cannot report its own
};

QString diffStatusId(DiffStatus status); // "same", "different", "only-in-file", "only-on-drive", "not-readable"

struct DiffEntry
{
    int index = -1;
    QString key;
    std::optional<qint64> fileValue;
    std::optional<qint64> driveValue; // for write-only: what DriveDesk last wrote, if anything
    DiffStatus status = DiffStatus::Same;
    Access access = Access::ReadWrite;
    bool communication = false; // changes how the drive talks: restored only when asked for
};

// Comparison of a backup file's values with a drive's, per dictionary parameter (ascending
// index). Parameters known on neither side, and indices not in the dictionary, are left out.
class ParameterDiff
{
    Q_DECLARE_TR_FUNCTIONS(dd::ParameterDiff)

public:
    static ParameterDiff compute(const ParameterDictionary &dictionary, const ParameterSet &file,
                                 const ParameterSet &drive);

    const QVector<DiffEntry> &entries() const { return m_entries; }
    const DiffEntry *entry(int index) const;
    int count(DiffStatus status) const;
    bool hasDifferences() const; // anything a restore would write

    // The values a restore writes, ascending index: Different, OnlyInFile and NotReadable
    // entries that are writable. Communication settings (address, baud, CAN format) are left
    // out unless `only` names them. A non-empty `only` restricts the selection to those
    // indices; naming a parameter the file has no value for, or a read-only one, is an error
    // (InvalidArgument / NotSupported) — nothing is selected then.
    Error selectForWrite(const QList<int> &only, QVector<DiffEntry> *out) const;

private:
    QVector<DiffEntry> m_entries;
};

} // namespace dd
