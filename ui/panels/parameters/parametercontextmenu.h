#pragma once

#include <QList>
#include <QMenu>
#include <functional>

namespace dd {

class ParameterTableModel;

// The Parameters table's context menu for the row under the pointer (and the selected rows):
// Copy (key, name, value and unit of the selected rows, tab-separated, one row a line),
// Reset to default (where the dictionary knows one: the default becomes a pending edit, to
// write like any other, undoable), Write this row (when its value is edited). Actions that do
// not apply are shown disabled, with the reason in their text.
class ParameterContextMenu : public QMenu
{
    Q_OBJECT
public:
    ParameterContextMenu(ParameterTableModel *model, int parameterIndex, const QList<int> &selected,
                         std::function<void(int)> writeRow, bool canWrite, QWidget *parent = nullptr);

    QAction *copyAction() const { return m_copy; }
    QAction *resetAction() const { return m_reset; }
    QAction *writeAction() const { return m_write; }
    // What Copy puts on the clipboard.
    static QString copyText(const ParameterTableModel *model, const QList<int> &parameters);

private:
    QAction *m_copy = nullptr;
    QAction *m_reset = nullptr;
    QAction *m_write = nullptr;
};

} // namespace dd
