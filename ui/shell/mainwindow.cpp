#include "ui/shell/mainwindow.h"

#include "core/drive/drivehub.h"
#include "ui/bus/bustreewidget.h"
#include "ui/bus/connectdialog.h"
#include "ui/bus/connectioncontroller.h"
#include "ui/bus/drivedirectory.h"
#include "ui/bus/scanprogresswidget.h"
#include "ui/bus/serialaccessdialog.h"
#include "ui/bus/statuspoller.h"
#include "ui/common/displaytext.h"
#include "ui/fleet/fleetactions.h"
#include "ui/framemonitor/framemonitordock.h"
#include "ui/help/helpactions.h"
#include "ui/linkhealth/linkhealthdock.h"
#include "ui/report/recordaction.h"
#include "ui/shell/aboutdialog.h"
#include "ui/shell/demolauncher.h"
#include "ui/shell/demomenu.h"
#include "ui/shell/languagemanager.h"
#include "ui/shell/loaddictionaryaction.h"
#include "ui/shell/recentfiles.h"
#include "ui/shell/statusbarwidget.h"
#include "ui/shell/stopaction.h"
#include "ui/shell/stopguard.h"
#include "ui/shell/stopreporter.h"
#include "ui/shell/stopreportview.h"
#include "ui/workspace/driveworkspace.h"

#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QEventLoop>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStyle>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>

namespace dd {

MainWindow::MainWindow(LanguageManager *language, QWidget *parent)
    : QMainWindow(parent)
    , m_language(language)
{
    setObjectName(QStringLiteral("mainWindow"));
    setWindowIcon(QApplication::windowIcon());
    if (!m_language) {
        m_language = new LanguageManager(this);
        m_language->apply(LanguageManager::savedLanguage());
    }
    createParts();
    createActions();
    createMenus();
    createToolBar();
    wireParts();
    // The frame monitor records from the start; View → Frame monitor shows it.
    auto *frames = new FrameMonitorDock(m_hub, this);
    addDock(frames, Qt::BottomDockWidgetArea);
    frames->hide();
    connect(frames, &FrameMonitorDock::errorOccurred, m_statusBar, &StatusBarWidget::countError);
    auto *health = new LinkHealthDock(m_hub, this); // View → Link health, from the same traffic
    addDock(health, Qt::BottomDockWidgetArea);
    health->hide();
    m_recent->load();
    retranslate();
    emit m_language->languageChanged(); // check the current language in the menu
    updateActions();
    m_poller->setEnabled(true);
    resize(1200, 760);
}

MainWindow::~MainWindow()
{
    // Close the links before the bench that simulates them goes away.
    m_poller->setEnabled(false);
    m_connections->disconnectAll();
    delete m_hub;
    m_hub = nullptr;
}

void MainWindow::createParts()
{
    m_hub = new DriveHub; // deleted explicitly, before the demo bench
    m_directory = new DriveDirectory(m_hub, this);
    m_poller = new StatusPoller(m_directory, this);
    m_connections = new ConnectionController(m_directory, m_poller, this);
    m_recent = new RecentFiles(this);
    m_demo = new DemoLauncher(m_connections, this);

    m_busTree = new BusTreeWidget(m_directory);
    m_busTree->setObjectName(QStringLiteral("busTree"));
    m_scanProgress = new ScanProgressWidget;
    auto *left = new QWidget;
    auto *leftLayout = new QVBoxLayout(left);
    leftLayout->setContentsMargins(0, 0, 0, 0);
    leftLayout->addWidget(m_busTree, 1);
    leftLayout->addWidget(m_scanProgress);
    m_busDock = new QDockWidget(this);
    m_busDock->setObjectName(QStringLiteral("busDock"));
    m_busDock->setWidget(left);
    m_busDock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable
                           | QDockWidget::DockWidgetClosable);
    addDockWidget(Qt::LeftDockWidgetArea, m_busDock);
    resizeDocks({m_busDock}, {460}, Qt::Horizontal);

    m_workspace = new DriveWorkspace(m_directory, this);
    m_workspace->setObjectName(QStringLiteral("driveWorkspace"));
    setCentralWidget(m_workspace);

    m_statusBar = new StatusBarWidget(m_hub, m_directory, this);
    setStatusBar(m_statusBar);
}

void MainWindow::createActions()
{
    m_stop = new StopAction(this);
    // Esc and F12 in every window of the application, with any dialog, menu or editor open,
    // and a STOP button in every dialog (StopGuard).
    new StopGuard(m_stop, this);
    connect(m_stop, &QAction::triggered, m_hub, &DriveHub::stopAll);
    // Then, drive by drive, what the STOP did (StopReporter), in the status bar.
    m_stopReporter = new StopReporter(m_directory, this);
    connect(m_stop, &QAction::triggered, m_stopReporter, &StopReporter::start);
    connect(m_stop, &QAction::triggered, this,
            [this] { m_statusBar->showLiveMessage([r = m_stopReporter] { return r->summary(); }); });
    connect(m_stopReporter, &StopReporter::updated, this,
            [this] { m_statusBar->showLiveMessage([r = m_stopReporter] { return r->summary(); }, 30000); });
    // The status bar cuts a long report: the whole of it in the button's tooltip and, on a
    // click, in a window of its own (StopReportView).
    m_stopReportButton = new QToolButton(m_statusBar);
    m_stopReportButton->setObjectName(QStringLiteral("stopReportButton"));
    m_stopReportButton->setAutoRaise(true);
    m_stopReportButton->hide();
    m_statusBar->addPermanentWidget(m_stopReportButton);
    connect(m_stopReportButton, &QToolButton::clicked, this, &MainWindow::showStopReport);
    const auto showReport = [this] {
        m_stopReportButton->setToolTip(m_stopReporter->details());
        m_stopReportButton->show();
    };
    connect(m_stop, &QAction::triggered, this, showReport);
    connect(m_stopReporter, &StopReporter::updated, this, showReport);

    m_connectAction = new QAction(style()->standardIcon(QStyle::SP_DriveNetIcon), QString(), this);
    m_connectAction->setObjectName(QStringLiteral("connectAction"));
    m_connectAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_K));
    connect(m_connectAction, &QAction::triggered, this, &MainWindow::showConnectDialog);

    m_disconnectAction = new QAction(style()->standardIcon(QStyle::SP_DialogCloseButton), QString(), this);
    m_disconnectAction->setObjectName(QStringLiteral("disconnectAction"));
    connect(m_disconnectAction, &QAction::triggered, this, &MainWindow::disconnectSelected);

    m_disconnectAllAction = new QAction(this);
    connect(m_disconnectAllAction, &QAction::triggered, m_connections, &ConnectionController::disconnectAll);

    m_demoAction = new QAction(style()->standardIcon(QStyle::SP_ComputerIcon), QString(), this);
    m_demoAction->setObjectName(QStringLiteral("demoAction"));
    connect(m_demoAction, &QAction::triggered, this, &MainWindow::startDemo);

    m_quitAction = new QAction(this);
    m_quitAction->setShortcut(QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);

    m_aboutAction = new QAction(this);
    m_aboutAction->setObjectName(QStringLiteral("aboutAction"));
    m_aboutAction->setMenuRole(QAction::AboutRole);
    connect(m_aboutAction, &QAction::triggered, this, &MainWindow::showAbout);
    m_aboutQtAction = new QAction(this);
    m_aboutQtAction->setObjectName(QStringLiteral("aboutQtAction"));
    m_aboutQtAction->setMenuRole(QAction::AboutQtRole);
    connect(m_aboutQtAction, &QAction::triggered, qApp, &QApplication::aboutQt);

    m_languageGroup = new QActionGroup(this);
    m_languageGroup->setExclusive(true);
    const auto addLanguage = [this](LanguageManager::Language language) {
        QAction *a = m_languageGroup->addAction(QString());
        a->setCheckable(true);
        a->setData(LanguageManager::languageId(language));
        connect(a, &QAction::triggered, this, [this, language] {
            m_language->apply(language);
            m_language->save();
        });
        return a;
    };
    m_langSystem = addLanguage(LanguageManager::Language::System);
    m_langEnglish = addLanguage(LanguageManager::Language::English);
    m_langChinese = addLanguage(LanguageManager::Language::Chinese);
    // Each language is named in itself, so that it can be found whatever the current one.
    m_langEnglish->setText(QStringLiteral("English"));
    m_langChinese->setText(QStringLiteral("中文 (简体)"));
}

void MainWindow::createMenus()
{
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->setObjectName(QStringLiteral("fileMenu"));
    m_fileMenu->addAction(m_connectAction);
    m_fileMenu->addAction(m_disconnectAction);
    m_fileMenu->addAction(m_disconnectAllAction);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_demoAction);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(new RecordAction(this));         // File → Commissioning record… (ui/report)
    m_fileMenu->addAction(new LoadDictionaryAction(this)); // for the selected drive
    m_fileMenu->addSeparator();
    m_recentMenu = m_fileMenu->addMenu(QString());
    m_recent->setMenu(m_recentMenu);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quitAction);

    m_viewMenu = menuBar()->addMenu(QString());
    m_viewMenu->setObjectName(QStringLiteral("viewMenu"));
    m_viewMenu->addAction(m_busDock->toggleViewAction());
    new FleetActions(m_directory, m_busTree, m_viewMenu, this); // Compare, several drives

    m_languageMenu = menuBar()->addMenu(QString());
    m_languageMenu->setObjectName(QStringLiteral("languageMenu"));
    m_languageMenu->addAction(m_langSystem);
    m_languageMenu->addSeparator();
    m_languageMenu->addAction(m_langEnglish);
    m_languageMenu->addAction(m_langChinese);

    menuBar()->addMenu(new DemoMenu(m_demo, this)); // Demo → Inject alarm
    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->setObjectName(QStringLiteral("helpMenu"));
    m_helpMenu->addAction(m_aboutAction);
    m_helpMenu->addAction(m_aboutQtAction);
    new HelpActions(this, m_helpMenu); // User guide (F1), Keyboard shortcuts
}

void MainWindow::createToolBar()
{
    m_toolBar = new QToolBar(this);
    m_toolBar->setObjectName(QStringLiteral("mainToolBar"));
    // Always visible: STOP must never be hidden, moved away or folded into an overflow menu
    // (it comes first, so a narrow window cuts the other buttons, not STOP).
    m_toolBar->setMovable(false);
    m_toolBar->setFloatable(false);
    m_toolBar->toggleViewAction()->setVisible(false);
    m_toolBar->setContextMenuPolicy(Qt::PreventContextMenu);
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_toolBar->addAction(m_connectAction);
    m_toolBar->addAction(m_disconnectAction);
    m_toolBar->addAction(m_demoAction);
    m_stop->addTo(m_toolBar);
    m_toolBar->insertSeparator(m_connectAction);
    addToolBar(Qt::TopToolBarArea, m_toolBar);
    setContextMenuPolicy(Qt::NoContextMenu);
}

void MainWindow::wireParts()
{
    connect(m_busTree, &BusTreeWidget::driveSelected, m_workspace, &DriveWorkspace::showDrive);
    connect(m_busTree, &BusTreeWidget::connectionSelected, this, &MainWindow::updateActions);
    connect(m_busTree, &BusTreeWidget::rescanRequested, m_connections, &ConnectionController::rescan);
    connect(m_busTree, &BusTreeWidget::disconnectRequested, m_connections, &ConnectionController::disconnectLink);
    connect(m_directory, &DriveDirectory::connectionAdded, this, &MainWindow::updateActions);
    connect(m_directory, &DriveDirectory::connectionRemoved, this, &MainWindow::updateActions);
    // Select the first drive found (of the preferred family, when one is set), so the window
    // shows something useful at once.
    connect(m_directory, &DriveDirectory::driveAdded, this, [this](int id, int address) {
        if (m_preferredFamily) {
            if (m_directory->discovered(id, address).family != *m_preferredFamily)
                return;
            m_preferredFamily.reset(); // the first one only
            m_busTree->selectDrive(id, address);
            return;
        }
        if (m_workspace->currentDrive().connectionId == 0 && m_busTree->selectedItems().isEmpty())
            m_busTree->selectDrive(id, address);
    });

    connect(m_connections, &ConnectionController::busyChanged, this, [this](bool busy) {
        if (busy)
            m_scanProgress->begin(tr("Connecting…"));
        else
            m_scanProgress->finish();
        updateActions();
    });
    connect(m_connections, &ConnectionController::stageChanged, m_scanProgress, &ScanProgressWidget::setStage);
    connect(m_connections, &ConnectionController::progress, m_scanProgress, &ScanProgressWidget::setProgress);
    connect(m_connections, &ConnectionController::foundCountChanged, m_scanProgress, &ScanProgressWidget::setFound);
    connect(m_scanProgress, &ScanProgressWidget::cancelRequested, m_connections, &ConnectionController::cancel);
    connect(m_connections, &ConnectionController::finished, this,
            [this](const QString &summary) { m_statusBar->showMessage(summary, 10000); });
    connect(m_connections, &ConnectionController::errorOccurred, m_statusBar, &StatusBarWidget::countError);
    connect(m_connections, &ConnectionController::serialAccessDenied, this, [this](const SerialAccessProblem &p) {
        auto *dialog = new SerialAccessDialog(p, this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->open();
    });
    connect(m_workspace, &DriveWorkspace::errorOccurred, m_statusBar, &StatusBarWidget::countError);
    connect(m_workspace, &DriveWorkspace::fileUsed, m_recent, &RecentFiles::add);
    connect(m_poller, &StatusPoller::pollFailed, m_statusBar,
            [this](int, int, const Error &e) { m_statusBar->countError(e); });
    connect(m_recent, &RecentFiles::fileTriggered, this, &MainWindow::openRecentFile);
    connect(m_demo, &DemoLauncher::failed, m_statusBar, &StatusBarWidget::countError);
    connect(m_language, &LanguageManager::languageChanged, this, [this] {
        const QString id = LanguageManager::languageId(m_language->language());
        for (QAction *a : m_languageGroup->actions())
            a->setChecked(a->data().toString() == id);
    });
}

void MainWindow::addDock(QDockWidget *dock, Qt::DockWidgetArea area)
{
    if (dock->objectName().isEmpty())
        qWarning("MainWindow::addDock: give the dock an objectName so its place is saved");
    addDockWidget(area, dock);
    m_viewMenu->addAction(dock->toggleViewAction());
}

void MainWindow::connectTo(const ConnectRequest &request)
{
    m_connections->connectTo(request);
}

bool MainWindow::startDemo()
{
    const Error e = m_demo->start();
    if (e.isError()) {
        m_statusBar->countError(e);
        QMessageBox::warning(this, tr("Demo bench"), e.message);
        return false;
    }
    updateActions();
    return true;
}

void MainWindow::showConnectDialog()
{
    ConnectDialog dialog(this);
    dialog.loadSettings();
    const int result = dialog.exec();
    if (result == QDialog::Accepted)
        connectTo(dialog.request());
    else if (result == ConnectDialog::DemoRequested)
        startDemo();
}

void MainWindow::disconnectSelected()
{
    int id = m_busTree->selectedConnection();
    const QList<int> ids = m_directory->connections();
    if (id == 0 && ids.size() == 1)
        id = ids.first();
    if (id > 0)
        m_connections->disconnectLink(id);
}

void MainWindow::updateActions()
{
    const QList<int> ids = m_directory->connections();
    m_disconnectAction->setEnabled(m_busTree->selectedConnection() > 0 || ids.size() == 1);
    m_disconnectAllAction->setEnabled(!ids.isEmpty());
    m_demoAction->setEnabled(!m_demo->isRunning());
}

void MainWindow::openRecentFile(const QString &path)
{
    if (!m_workspace->openFile(path))
        m_statusBar->showMessage(tr("Select a drive first: %1 is opened in one of its tabs.").arg(path), 8000);
}

void MainWindow::showStopReport()
{
    if (!m_stopReportView)
        m_stopReportView = new StopReportView(m_stopReporter, this);
    m_stopReportView->show();
    m_stopReportView->raise();
    m_stopReportView->activateWindow();
}

void MainWindow::showAbout()
{
    AboutDialog(this).exec();
}

void MainWindow::restoreLayout()
{
    QSettings s;
    restoreGeometry(s.value(QStringLiteral("mainWindow/geometry")).toByteArray());
    restoreState(s.value(QStringLiteral("mainWindow/state")).toByteArray());
    m_toolBar->show(); // never restore a hidden STOP
}

void MainWindow::saveLayout() const
{
    QSettings s;
    s.setValue(QStringLiteral("mainWindow/geometry"), saveGeometry());
    s.setValue(QStringLiteral("mainWindow/state"), saveState());
}

QStringList MainWindow::drivesInMotionOrEnabled() const
{
    QStringList out;
    for (int id : m_directory->connections())
        for (int address : m_directory->drives(id)) {
            const DriveStatus s = m_directory->info(id, address).status;
            const QString name = DisplayText::driveName(m_directory->discovered(id, address).family, address);
            if (s.running)
                out << tr("%1 is moving").arg(name);
            else if (s.enabled)
                out << tr("%1 has its power stage on").arg(name);
        }
    return out;
}

bool MainWindow::confirmQuit()
{
    const QStringList live = drivesInMotionOrEnabled();
    if (live.isEmpty())
        return true;
    QMessageBox box(QMessageBox::Warning, tr("Quit DriveDesk?"),
                    tr("%1.\n\nQuitting ends DriveDesk's control of these drives. STOP them all (as the "
                       "STOP button does) and quit?")
                        .arg(live.join(tr("; "))),
                    QMessageBox::NoButton, this);
    box.setObjectName(QStringLiteral("quitConfirmation"));
    QPushButton *stopAndQuit = box.addButton(tr("STOP and quit"), QMessageBox::AcceptRole);
    stopAndQuit->setObjectName(QStringLiteral("stopAndQuit"));
    QPushButton *cancel = box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(cancel);
    box.setEscapeButton(cancel);
    box.exec();
    if (box.clickedButton() != stopAndQuit)
        return false;
    // STOP, then wait until every drive's outcome is known (StopReporter: at most its
    // confirmation time), so that the stop is on the wire before the links close.
    QEventLoop wait;
    connect(m_stopReporter, &StopReporter::finished, &wait, &QEventLoop::quit);
    QTimer::singleShot(StopReporter::ConfirmTimeoutMs + 1000, &wait, &QEventLoop::quit);
    m_stop->trigger();
    if (m_stopReporter->isRunning())
        wait.exec(QEventLoop::ExcludeUserInputEvents);
    return true;
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (m_closing) { // a second close while the first one asks or waits
        event->ignore();
        return;
    }
    m_closing = true;
    const bool quit = confirmQuit();
    m_closing = false;
    if (!quit) {
        event->ignore();
        return;
    }
    saveLayout();
    m_recent->save();
    QMainWindow::closeEvent(event);
}

void MainWindow::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QMainWindow::changeEvent(event);
}

void MainWindow::retranslate()
{
    // The platform adds the application's name (" — DriveDesk"): not repeated here.
    setWindowTitle(tr("Commissioning workbench"));
    m_fileMenu->setTitle(tr("&File"));
    m_viewMenu->setTitle(tr("&View"));
    m_languageMenu->setTitle(tr("&Language"));
    m_helpMenu->setTitle(tr("&Help"));
    m_recentMenu->setTitle(tr("&Recent files"));
    m_connectAction->setText(tr("&Connect…"));
    m_connectAction->setToolTip(tr("Open a serial port or a CAN interface and scan it for drives (%1)")
                                    .arg(m_connectAction->shortcut().toString(QKeySequence::NativeText)));
    m_disconnectAction->setText(tr("&Disconnect"));
    m_disconnectAction->setToolTip(tr("Close the selected connection"));
    m_disconnectAllAction->setText(tr("Disconnect &all"));
    m_demoAction->setText(tr("De&mo bench"));
    m_demoAction->setToolTip(tr("Start simulated drives of every family and connect to them"));
    m_quitAction->setText(tr("&Quit"));
    m_aboutAction->setText(tr("&About DriveDesk"));
    m_aboutQtAction->setText(tr("About &Qt"));
    m_langSystem->setText(tr("&System language"));
    m_busDock->setWindowTitle(tr("Bus"));
    m_busDock->toggleViewAction()->setText(tr("&Bus tree"));
    m_toolBar->setWindowTitle(tr("Main tool bar"));
    m_stop->retranslate();
    m_stopReportButton->setText(tr("STOP report…"));
    if (m_stopReportButton->isVisibleTo(m_statusBar))
        m_stopReportButton->setToolTip(m_stopReporter->details());
    m_recent->rebuildMenu();
}

} // namespace dd
