#pragma once

#include "core/common/error.h"
#include "ui/workspace/drivecontext.h"

#include <QMap>
#include <QPair>
#include <QStackedWidget>

class QLabel;
class QTabWidget;

namespace dd {

class AlarmLog;
class DriveDirectory;
class DrivePanel;
class DriveParameters;

// The central area: the tabs of the selected drive. Each drive gets its own QTabWidget of
// panels (created on first selection, see drivepanels.h) so that a panel keeps its state
// while another drive is shown; switching drives keeps the same tab when the other drive
// has it. With no drive selected a hint is shown.
class DriveWorkspace : public QStackedWidget
{
    Q_OBJECT
public:
    explicit DriveWorkspace(DriveDirectory *directory, QWidget *parent = nullptr);

    // Shows the drive's tabs (id 0: the hint page).
    void showDrive(int id, int address);
    DriveContext currentDrive() const;
    QTabWidget *tabsFor(int id, int address) const;
    QList<DrivePanel *> panelsFor(int id, int address) const;
    // The parameter values every panel of the drive shares.
    DriveParameters *parametersFor(int id, int address) const;
    // The drive's alarm history, recorded from the moment it was found (null: no such drive).
    AlarmLog *alarmLogFor(int id, int address) const { return m_alarmLogs.value(Key(id, address)); }
    // The tab to show when a drive is shown (a panel id: "overview", "trend", ...).
    void setPreferredPanel(const QString &panelId);
    QString preferredPanel() const { return m_currentPanelId; }
    // Offers a file to the selected drive's panels; shows the panel that took it.
    bool openFile(const QString &path);

signals:
    void errorOccurred(const dd::Error &error);
    void currentDriveChanged(int id, int address);
    void fileUsed(const QString &path);

protected:
    void changeEvent(QEvent *event) override;

private:
    using Key = QPair<int, int>;

    QTabWidget *createTabs(int id, int address);
    AlarmLog *alarmLog(int id, int address); // made when missing
    void removeConnection(int id);
    void onDriveChanged(int id, int address);
    void updateActive();
    void retranslate();

    DriveDirectory *m_directory = nullptr;
    QLabel *m_hint = nullptr;
    QMap<Key, QTabWidget *> m_tabs;
    QMap<Key, AlarmLog *> m_alarmLogs;
    Key m_current{0, 0};
    QString m_currentPanelId; // the tab to keep when switching drives
};

} // namespace dd
