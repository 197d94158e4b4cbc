#pragma once

#include "core/params/parameterdiff.h"

#include <QTableWidget>

namespace dd {

class ParameterDictionary;

// The Backup tab's comparison of a backup file with the drive: one row per parameter, a
// checkbox on every row a restore can write (different, not read from the drive,
// write-only; never read-only ones). The rows a plain restore would write are ticked;
// communication settings (address, baud rate) are not, so that a restore does not cut the
// connection unless the user asks for it. Identical parameters are hidden unless shown.
class BackupDiffTable : public QTableWidget
{
    Q_OBJECT
public:
    enum Column { Parameter, FileValue, DriveValue, Status, ColumnCount };

    explicit BackupDiffTable(QWidget *parent = nullptr);

    void setDiff(const ParameterDiff &diff, const ParameterDictionary &dictionary);
    void clearDiff();
    const ParameterDiff &diff() const { return m_diff; }

    void setShowIdentical(bool show);
    bool showIdentical() const { return m_showIdentical; }

    QList<int> checkableIndices() const;
    QList<int> checkedIndices() const;
    void setChecked(int parameterIndex, bool checked);
    void setAllChecked(bool checked);
    int rowOf(int parameterIndex) const; // -1 when not listed

    static QString statusText(DiffStatus status);
    void retranslate();

signals:
    void checkedChanged();

private:
    void fill(bool keepChecks);
    void applyVisibility();

    ParameterDiff m_diff;
    const ParameterDictionary *m_dictionary = nullptr;
    bool m_showIdentical = false;
    bool m_filling = false;
};

} // namespace dd
