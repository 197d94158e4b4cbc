#pragma once

#include "ui/bus/connectrequest.h"

#include "core/common/family.h"

#include <QMainWindow>

#include <optional>

class QActionGroup;
class QDockWidget;
class QMenu;
class QToolBar;
class QToolButton;

namespace dd {

class BusTreeWidget;
class ConnectionController;
class DemoLauncher;
class DriveDirectory;
class DriveHub;
class DriveWorkspace;
class LanguageManager;
class RecentFiles;
class ScanProgressWidget;
class StatusBarWidget;
class StatusPoller;
class StopAction;
class StopReporter;
class StopReportView;

// The workbench window. It only assembles and wires the parts:
//   DriveHub (I/O thread) → DriveDirectory (the GUI's picture of the bus) → BusTreeWidget
//   (left dock), DriveWorkspace (central: per-drive tabs of DrivePanels), StatusBarWidget;
//   ConnectionController (connect / detect / scan, ScanProgressWidget under the tree),
//   StatusPoller (live state), DemoLauncher (the simulated bench), LanguageManager,
//   RecentFiles, StopAction (the STOP button and its shortcuts).
// Other docks (frame monitor, alarms ...) plug in with addDock().
class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    // `language`: an applied LanguageManager to use (main() sets it up before parsing the
    // command line); nullptr: the window makes its own and applies the saved language.
    explicit MainWindow(LanguageManager *language = nullptr, QWidget *parent = nullptr);
    ~MainWindow() override;

    DriveHub *hub() const { return m_hub; }
    DriveDirectory *directory() const { return m_directory; }
    ConnectionController *connections() const { return m_connections; }
    BusTreeWidget *busTree() const { return m_busTree; }
    DriveWorkspace *workspace() const { return m_workspace; }
    StatusBarWidget *statusBarWidget() const { return m_statusBar; }
    ScanProgressWidget *scanProgress() const { return m_scanProgress; }
    StatusPoller *statusPoller() const { return m_poller; }
    LanguageManager *languageManager() const { return m_language; }
    RecentFiles *recentFiles() const { return m_recent; }
    DemoLauncher *demo() const { return m_demo; }
    StopAction *stopAction() const { return m_stop; }
    StopReporter *stopReporter() const { return m_stopReporter; }
    // The status bar's "STOP report" button (shown from the first STOP on; its tooltip is the
    // whole report) and the window it opens (nullptr until opened).
    QToolButton *stopReportButton() const { return m_stopReportButton; }
    StopReportView *stopReportView() const { return m_stopReportView; }
    void showStopReport();
    QMenu *fileMenu() const { return m_fileMenu; }
    QMenu *viewMenu() const { return m_viewMenu; }

    // Adds a dock and its toggle to the View menu (frame monitor, alarm log, ...).
    void addDock(QDockWidget *dock, Qt::DockWidgetArea area);

    void connectTo(const ConnectRequest &request);
    // File → Demo bench: starts the simulated bench and connects to it; false (with a
    // message) if it could not start.
    bool startDemo();
    void showConnectDialog();
    void disconnectSelected();
    // Select the first drive of `family` found from now on (instead of the first drive of
    // any family): `drivedesk --drive servo-can`.
    void setPreferredFamily(Family family) { m_preferredFamily = family; }
    // Window geometry and dock layout (QSettings "mainWindow/...").
    void restoreLayout();
    void saveLayout() const;

protected:
    void closeEvent(QCloseEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void createParts();
    void createActions();
    void createMenus();
    void createToolBar();
    void wireParts();
    void retranslate();
    void updateActions();
    void openRecentFile(const QString &path);
    void showAbout();
    // "servo-can 1 is moving", "… has its power stage on": what quitting would leave alone.
    QStringList drivesInMotionOrEnabled() const;
    // With a drive enabled or moving: asks, and STOPs every drive on "STOP and quit".
    bool confirmQuit();

    DriveHub *m_hub = nullptr;
    DriveDirectory *m_directory = nullptr;
    StatusPoller *m_poller = nullptr;
    ConnectionController *m_connections = nullptr;
    LanguageManager *m_language = nullptr;
    RecentFiles *m_recent = nullptr;
    DemoLauncher *m_demo = nullptr;
    BusTreeWidget *m_busTree = nullptr;
    ScanProgressWidget *m_scanProgress = nullptr;
    DriveWorkspace *m_workspace = nullptr;
    StatusBarWidget *m_statusBar = nullptr;
    QDockWidget *m_busDock = nullptr;
    QToolBar *m_toolBar = nullptr;
    std::optional<Family> m_preferredFamily; // see setPreferredFamily()
    bool m_closing = false;                  // closeEvent() is asking or waiting

    QMenu *m_fileMenu = nullptr;
    QMenu *m_recentMenu = nullptr;
    QMenu *m_viewMenu = nullptr;
    QMenu *m_languageMenu = nullptr;
    QMenu *m_helpMenu = nullptr;
    StopAction *m_stop = nullptr;
    StopReporter *m_stopReporter = nullptr;
    QToolButton *m_stopReportButton = nullptr;
    StopReportView *m_stopReportView = nullptr;
    QAction *m_connectAction = nullptr;
    QAction *m_disconnectAction = nullptr;
    QAction *m_disconnectAllAction = nullptr;
    QAction *m_demoAction = nullptr;
    QAction *m_quitAction = nullptr;
    QAction *m_aboutAction = nullptr;
    QAction *m_aboutQtAction = nullptr;
    QActionGroup *m_languageGroup = nullptr;
    QAction *m_langSystem = nullptr;
    QAction *m_langEnglish = nullptr;
    QAction *m_langChinese = nullptr;
};

} // namespace dd
