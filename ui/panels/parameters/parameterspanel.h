#pragma once

#include "ui/workspace/drivepanel.h"

#include <memory>

class QAction;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSortFilterProxyModel;
class QTableView;
class QUndoStack;

namespace dd {

class ParameterContextMenu;

class ParameterDictionary;
class ParameterTableModel;
class ParameterValueDelegate;

// The Parameters tab: every parameter of the drive in a table (ParameterTableModel) with
// index, name in the UI language, value, the drive's value, unit, range, default, access
// and the outcome of the last write. Values are edited in place; an out-of-range or
// malformed value is refused on the spot with the reason (ParameterValueDelegate) and
// nothing is sent. Edits can be undone (QUndoStack); a search box filters by index, key
// or name (any language). Read all / Write selected / Write all changed go through the hub;
// every write is read back by the drive and each row shows verified or failed.
class ParametersPanel : public DrivePanel
{
    Q_OBJECT
public:
    explicit ParametersPanel(const DriveContext &context, QWidget *parent = nullptr);
    ~ParametersPanel() override;

    QString panelId() const override { return QStringLiteral("parameters"); }
    QString title() const override;

    void readAll();
    void writeSelected();
    void writeAllChanged();
    bool isBusy() const { return m_busy; }

    ParameterTableModel *model() const { return m_model; }
    QSortFilterProxyModel *proxy() const { return m_proxy; }
    QTableView *view() const { return m_view; }
    QUndoStack *undoStack() const { return m_undo; }
    QString message() const;
    // Most names of the dictionary in use are generic ("Parameter 12"): the tab says how to
    // load the drive's own dictionary.
    bool namesAreGeneric() const;
    // Loads a parameter dictionary (JSON, docs/dictionaries.md) for this drive: validated
    // whole against the drive's family; on success the table is relabelled and the drive
    // validates writes with it (for this session); on failure nothing changes and the
    // message line says why.
    Error loadDictionary(const QString &path);
    // File → Load dictionary…: asks for the file, then loadDictionary().
    void chooseDictionary();
    bool openFile(const QString &path) override;
    // The table's context menu for a row (made on a right click; tests trigger its actions).
    ParameterContextMenu *contextMenuFor(int parameterIndex);

signals:
    // A read or a write ended (tests, and whoever waits for the drive).
    void operationFinished(bool ok);

protected:
    void activeChanged(bool active) override;
    void driveInfoChanged(const DriveInfo &info) override;
    void retranslate() override;

private:
    void buildSearch();
    void buildButtons();
    void buildUndoActions();
    void buildTable();
    void connectMessages();
    void connectSharedValues();
    void layOut();
    void write(const QList<int> &indices, bool onlySelected);
    bool confirmCommunicationWrites(const QList<int> &indices);
    void onRead(const DriveResult &result, std::shared_ptr<const ParameterDictionary> dictionary);
    void onWritten(const DriveResult &result, const QList<int> &requested);
    void setBusy(bool busy, const QString &what = {});
    void setMessage(const QString &text, MessageKind kind);
    void updateActions();
    void updateCount();
    void updateGenericHint();
    void maybeReadFirstTime();
    QList<int> selectedParameters() const;

    ParameterTableModel *m_model = nullptr;
    QSortFilterProxyModel *m_proxy = nullptr;
    ParameterValueDelegate *m_delegate = nullptr;
    QUndoStack *m_undo = nullptr;
    QTableView *m_view = nullptr;
    QLineEdit *m_search = nullptr;
    QLabel *m_count = nullptr;
    QPushButton *m_readAll = nullptr;
    QPushButton *m_writeSelected = nullptr;
    QPushButton *m_writeChanged = nullptr;
    QPushButton *m_undoButton = nullptr;
    QPushButton *m_redoButton = nullptr;
    QAction *m_undoAction = nullptr;
    QAction *m_redoAction = nullptr;
    QProgressBar *m_progress = nullptr;
    QLabel *m_message = nullptr;
    QLabel *m_genericHint = nullptr;
    std::shared_ptr<const ParameterDictionary> m_dictionary; // the drive's
    QString m_modelName;                                     // the drive model the rows are chosen for
    bool m_busy = false;
    bool m_everRead = false;
    bool m_columnsSized = false;
};

} // namespace dd
