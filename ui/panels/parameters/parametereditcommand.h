#pragma once

#include <QCoreApplication>
#include <QPointer>
#include <QUndoCommand>
#include <optional>

namespace dd {

class ParameterTableModel;

// One edit of a parameter value in the Parameters tab, for its undo stack: redo sets the
// new edit, undo puts the old one back (nullopt: the row showed the drive's value).
// Undo after the edit was written: the drive's value from before the write comes back into
// the editor as a pending change, marked as such (write it to restore it on the drive).
class ParameterEditCommand : public QUndoCommand
{
    Q_DECLARE_TR_FUNCTIONS(dd::ParameterEditCommand)
public:
    ParameterEditCommand(ParameterTableModel *model, int parameterIndex, std::optional<qint64> before,
                         std::optional<qint64> after);

    void undo() override;
    void redo() override;

private:
    QPointer<ParameterTableModel> m_model;
    int m_index;
    std::optional<qint64> m_before;
    std::optional<qint64> m_after;
    std::optional<qint64> m_driveBefore; // the drive's value when the edit was made
};

} // namespace dd
