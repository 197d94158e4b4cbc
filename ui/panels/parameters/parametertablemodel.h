#pragma once

#include "core/common/error.h"
#include "core/drive/drivetypes.h"
#include "core/params/parameterinfo.h"
#include "core/params/parameterset.h"

#include <QAbstractTableModel>
#include <QPointer>
#include <QSet>
#include <QVector>
#include <memory>
#include <optional>

#include <QUndoStack>

namespace dd {

class ParameterDictionary;

// The parameters of one drive as the Parameters tab shows them: one row per dictionary
// parameter that applies to the drive's model, with the drive's value (as last read, or for
// a write-only parameter the value last written), the edited value and the outcome of the
// last write. Editing the Value column validates the text (ParameterValueValidator) and,
// with an undo stack set, goes through it (ParameterEditCommand); a refused edit changes
// nothing and emits editRefused() with the reason.
class ParameterTableModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { Mark, Index, Key, Name, Value, DriveValue, Unit, Range, Default, Access, State, ColumnCount };
    enum Role {
        SearchRole = Qt::UserRole + 1, // "12 PA12 <name in every language>"
        ParameterIndexRole             // the dictionary index of the row
    };
    // The outcome of the last write of a parameter.
    enum class WriteState { None, Verified, WrittenOnly, Failed, NotAttempted };

    explicit ParameterTableModel(QObject *parent = nullptr);
    ~ParameterTableModel() override;

    // The rows: every parameter of `dictionary` that applies to `model` (parameters marked
    // for particular models only when `model` is one of them). Values and edits of
    // parameters that remain are kept.
    void setDictionary(std::shared_ptr<const ParameterDictionary> dictionary, const QString &model = {});
    const ParameterDictionary *dictionary() const { return m_dictionary.get(); }
    void setUndoStack(QUndoStack *stack) { m_undo = stack; }

    int rowOf(int parameterIndex) const; // -1 when not shown
    int parameterAt(int row) const;
    const ParameterInfo *info(int parameterIndex) const;
    QList<int> parameterIndices() const; // every row, in order
    QList<int> readableIndices() const;  // rows that can be read from the drive

    ParameterValue driveValue(int parameterIndex) const;
    std::optional<qint64> editedValue(int parameterIndex) const;
    // The value the row shows: the edited one, else the drive's.
    std::optional<qint64> value(int parameterIndex) const;
    // Edited, and different from the drive's value (or the drive's is not known).
    bool isChanged(int parameterIndex) const;
    QList<int> changedIndices() const;
    WriteState writeState(int parameterIndex) const;
    QString writeMessage(int parameterIndex) const;

    // Values read from the drive (edits equal to a new value are dropped), or for write-only
    // parameters the values the drive reports as last written (source LastWritten).
    void setDriveValues(const QMap<int, qint64> &values, ValueSource source = ValueSource::ReadFromDrive);
    // The outcome of a write of `requested`: verified and written-only values become the
    // drive's and their edits are dropped; failed ones keep their edits; parameters without
    // a result are marked not attempted.
    void applyWriteResults(const QList<ParameterWriteResult> &results, const QList<int> &requested);
    // Sets (nullopt: drops) an edit without validation or undo; for ParameterEditCommand.
    // `undoneWrite`: the edit brings back the value the drive had before a write (shown
    // marked as such until written or edited).
    void setEditedValue(int parameterIndex, std::optional<qint64> value, bool undoneWrite = false);
    bool isUndoneWrite(int parameterIndex) const;
    // Parameters written since the last save to EEPROM (servo-modbus): marked in the table.
    void setUnsaved(const QSet<int> &indices);
    bool isUnsaved(int parameterIndex) const { return m_unsaved.contains(parameterIndex); }
    // Validates `text` for the parameter; on success *value is set.
    Error checkText(int parameterIndex, const QString &text, qint64 *value) const;

    // Every text again (language change).
    void retranslate();

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;

signals:
    void editRefused(int parameterIndex, const dd::Error &reason);
    // An edit was set or dropped (the Changed mark may have moved).
    void editsChanged();

private:
    struct Row
    {
        ParameterInfo info;
        ParameterValue drive;
        std::optional<qint64> edited;
        WriteState state = WriteState::None;
        QString message;
        bool undoneWrite = false; // the edit is an undone write (see setEditedValue)
    };

    Row *rowFor(int parameterIndex);
    const Row *rowFor(int parameterIndex) const;
    bool rowChanged(const Row &r) const;
    void emitRowChanged(int row);
    QVariant display(const Row &r, int column) const;
    QVariant toolTip(const Row &r, int column, bool changed) const;
    QString driveText(const Row &r) const;
    QString stateText(const Row &r) const;
    QString searchText(const Row &r) const;

    std::shared_ptr<const ParameterDictionary> m_dictionary;
    QVector<Row> m_rows;
    QHash<int, int> m_rowOf;
    QPointer<QUndoStack> m_undo;
    QSet<int> m_unsaved;
};

} // namespace dd
