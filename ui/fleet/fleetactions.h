#pragma once

#include <QObject>

class QAction;
class QMenu;
class QWidget;

namespace dd {

class BusTreeWidget;
class DriveDirectory;

// The main window's ways into the several-drive views: a "Compare parameters…" entry in a
// menu, and the bus tree's "Apply backup…", "Copy parameters from drive N…" and
// "Compare…" on the selected drives. Opens CompareView and FleetApplyDialog (non-modal,
// deleted when closed). Keeps its action's text in the current language.
class FleetActions : public QObject
{
    Q_OBJECT
public:
    FleetActions(DriveDirectory *directory, BusTreeWidget *busTree, QMenu *menu, QWidget *window);

    QAction *compareAction() const { return m_compare; }

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void openCompare(int connectionId, const QList<int> &addresses);
    void applyBackup(int connectionId, const QList<int> &addresses);
    void copyParameters(int connectionId, int source, const QList<int> &targets);
    void retranslate();

    DriveDirectory *m_directory = nullptr;
    QWidget *m_window = nullptr;
    QAction *m_compare = nullptr;
};

} // namespace dd
