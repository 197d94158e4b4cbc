#pragma once

#include <QTreeWidget>

namespace dd {

class DriveDirectory;

// The bus tree: connections, and under each the drives found on it with family, address,
// firmware and live state (idle / running, enabled, position, alarm badge). A view of the
// DriveDirectory; selecting a drive emits driveSelected().
class BusTreeWidget : public QTreeWidget
{
    Q_OBJECT
public:
    enum Column { NameColumn, StateColumn, PositionColumn, FirmwareColumn, ColumnCount };
    enum Role { ConnectionRole = Qt::UserRole + 1, AddressRole };

    explicit BusTreeWidget(DriveDirectory *directory, QWidget *parent = nullptr);

    QTreeWidgetItem *connectionItem(int id) const;
    QTreeWidgetItem *driveItem(int id, int address) const;
    // Selects the drive (or clears the selection with id 0).
    void selectDrive(int id, int address);
    int selectedConnection() const; // 0: none (a drive's connection counts)
    // The selected drives of connection `id` (several with Ctrl / Shift), ascending.
    QList<int> selectedDrives(int id) const;

signals:
    // (0, 0): nothing or a connection is selected.
    void driveSelected(int id, int address);
    void connectionSelected(int id);
    void rescanRequested(int id);
    void disconnectRequested(int id);
    // Several drives: the context menu's "Apply backup…", "Copy parameters from drive N…"
    // and "Compare…" on the selected drives of a connection.
    void applyBackupRequested(int id, const QList<int> &addresses);
    void copyParametersRequested(int id, int sourceAddress, const QList<int> &targets);
    void compareRequested(int id, const QList<int> &addresses);

protected:
    void changeEvent(QEvent *event) override;

private:
    void onConnectionAdded(int id);
    void onConnectionRemoved(int id);
    void onDriveAdded(int id, int address);
    void updateConnection(int id);
    void updateDrive(int id, int address);
    void onSelectionChanged();
    void showContextMenu(const QPoint &pos);
    void retranslate();

    DriveDirectory *m_directory = nullptr;
};

} // namespace dd
