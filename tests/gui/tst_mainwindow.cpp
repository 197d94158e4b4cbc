// The main window: construction, the STOP button and its shortcuts, live language switch,
// recent files, saved layout. Offscreen, with settings in a temporary directory.
#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/link/trafficrecord.h"
#include "sim/bench/demobench.h"
#include "tests/gui/overflowcheck.h"
#include "ui/bus/bustreewidget.h"
#include "ui/bus/connectioncontroller.h"
#include "ui/bus/drivedirectory.h"
#include "ui/help/helpactions.h"
#include "ui/help/shortcutsdialog.h"
#include "ui/help/userguidedialog.h"
#include "ui/panels/alarms/alarmspanel.h"
#include "ui/shell/demomenu.h"
#include "ui/shell/languagemanager.h"
#include "ui/shell/mainwindow.h"
#include "ui/shell/recentfiles.h"
#include "ui/shell/statusbarwidget.h"
#include "ui/shell/stopaction.h"
#include "ui/shell/stopreporter.h"
#include "ui/shell/stopreportview.h"
#include "ui/workspace/drivepanel.h"
#include "ui/workspace/driveworkspace.h"

#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <QToolButton>

using namespace dd;

class TestMainWindow : public QObject
{
    Q_OBJECT

    QTemporaryDir m_settingsDir;

    static QStringList menuActionTexts(MainWindow &w, const QString &menu)
    {
        QStringList out;
        if (auto *m = w.findChild<QMenu *>(menu))
            for (QAction *a : m->actions())
                out << a->text();
        return out;
    }

    static QStringList menuTitles(MainWindow &w)
    {
        QStringList out;
        for (QAction *a : w.menuBar()->actions())
            out << a->text();
        return out;
    }

    template <typename Cond>
    static bool waitFor(Cond cond, int timeoutMs)
    {
        QDeadlineTimer deadline(timeoutMs);
        while (!cond() && !deadline.hasExpired())
            QTest::qWait(10); // an event loop turn, not a timed assertion
        return cond();
    }

    static int connectionOf(DriveDirectory *dir, Family f)
    {
        for (int id : dir->connections())
            if (dir->connectionSettings(id).family == f)
                return id;
        return 0;
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_settingsDir.isValid());
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
        QCoreApplication::setOrganizationName(QStringLiteral("DriveDeskTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_mainwindow"));
        QSettings().setValue(QStringLiteral("language"), QStringLiteral("en"));
    }

    void constructsAndShows()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.busTree()->isVisible());
        QVERIFY(w.workspace()->isVisible());
        QCOMPARE(menuTitles(w), QStringList({"&File", "&View", "&Language", "&Demo", "&Help"}));
        // The platform adds the application's name: the title does not repeat it.
        QCOMPARE(w.windowTitle(), QStringLiteral("Commissioning workbench"));
    }

    void stopButtonIsAlwaysVisible()
    {
        MainWindow w;
        w.resize(320, 400); // narrow: other tool buttons may be cut, STOP may not
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto *button = w.findChild<QToolButton *>(QStringLiteral("stopButton"));
        QVERIFY(button);
        QVERIFY(button->isVisible());
        QVERIFY(button->isEnabled());
        QCOMPARE(button->defaultAction(), w.stopAction());
        auto *bar = w.findChild<QToolBar *>(QStringLiteral("mainToolBar"));
        QVERIFY(bar);
        QCOMPARE(bar->actions().first(), static_cast<QAction *>(w.stopAction()));
        QVERIFY(!bar->isMovable());
        QVERIFY(!bar->toggleViewAction()->isVisible()); // cannot be hidden from a menu
        // The tooltip names the shortcuts.
        QVERIFY2(button->toolTip().contains(QLatin1String("Esc")), qPrintable(button->toolTip()));
        QVERIFY2(button->toolTip().contains(QLatin1String("F12")), qPrintable(button->toolTip()));
    }

    void stopShortcutsTriggerStop_data()
    {
        QTest::addColumn<int>("key");
        QTest::newRow("F12") << int(Qt::Key_F12);
        QTest::newRow("Esc") << int(Qt::Key_Escape);
    }

    void stopShortcutsTriggerStop()
    {
        QFETCH(int, key);
        MainWindow w;
        w.show();
        QApplication::setActiveWindow(&w);
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QSignalSpy spy(w.stopAction(), &QAction::triggered);
        // From anywhere in the window: the bus tree has the focus here.
        w.busTree()->setFocus();
        QTest::keyClick(w.busTree(), Qt::Key(key));
        QCOMPARE(spy.count(), 1);
        // The status bar confirms it: nothing is connected.
        QCOMPARE(w.statusBar()->currentMessage(), QStringLiteral("STOP sent; no drive is connected."));
    }

    void stopReportsEachDrive()
    {
        // The demo bench: one drive of each family. servo-can and shuoke move; STOP sends
        // each family's stop frame and the report says, per drive, what the drive's own
        // state confirms; servo-modbus has no stop command and is reported as such.
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        DriveDirectory *dir = w.directory();
        QVERIFY(w.startDemo());
        QVERIFY(waitFor(
            [&] {
                int n = 0;
                for (int id : dir->connections())
                    for (int a : dir->drives(id))
                        n += dir->info(id, a).valid ? 1 : 0;
                return n == 3 && !w.connections()->isBusy();
            },
            20000));
        const int can = connectionOf(dir, Family::ServoCan);
        const int shuoke = connectionOf(dir, Family::Shuoke);
        const int modbus = connectionOf(dir, Family::ServoModbus);
        QVERIFY(can && shuoke && modbus);
        int started = 0;
        for (int id : {can, shuoke})
            w.hub()->run(
                id, DemoBench::Address, [](Drive &d) { return d.moveRelative(100000000, 300); },
                [&started](const DriveResult &r) { started += r.ok() ? 1 : 0; });
        QVERIFY(waitFor([&] { return started == 2; }, 5000));

        QSignalSpy traffic(w.hub(), &DriveHub::trafficRecorded);
        QSignalSpy finished(w.stopReporter(), &StopReporter::finished);
        w.stopAction()->trigger();
        QVERIFY(finished.wait(5000));

        bool canStop = false, shuokeStop = false, modbusTx = false;
        for (const QList<QVariant> &args : std::as_const(traffic)) {
            const auto rec = args.at(1).value<TrafficRecord>();
            if (rec.direction != TrafficRecord::Direction::Tx)
                continue;
            const int id = args.at(0).toInt();
            // servo-can station 1 (ID 0x065): 0x28 stop and disable.
            if (id == can && rec.canId == 0x065 && rec.bytes.toHex() == "01280000000000ff")
                canStop = true;
            // shuoke: the broadcast emergency stop, address 0, command 0x3C.
            if (id == shuoke && rec.bytes.startsWith(QByteArray::fromHex("003c")))
                shuokeStop = true;
            if (id == modbus && rec.note.contains(QLatin1String("stop"), Qt::CaseInsensitive))
                modbusTx = true;
        }
        QVERIFY(canStop);
        QVERIFY(shuokeStop);
        QVERIFY(!modbusTx); // the family has no stop command: nothing pretends to be one

        QHash<int, StopReporter::Outcome> outcome;
        DriveStatus modbusState;
        for (const StopReporter::Line &l : w.stopReporter()->lines()) {
            outcome.insert(l.connectionId, l.outcome);
            if (l.connectionId == modbus)
                modbusState = l.status;
        }
        QCOMPARE(outcome.value(can), StopReporter::Outcome::Stopped);
        QCOMPARE(outcome.value(shuoke), StopReporter::Outcome::Stopped);
        QVERIFY(!dir->info(can, 1).status.running);
        QVERIFY(!dir->info(shuoke, 1).status.running);
        // servo-modbus: what its state says, not "stopped".
        QVERIFY(modbusState.online);
        const bool modbusRunning = modbusState.running;
        QCOMPARE(outcome.value(modbus),
                 modbusRunning ? StopReporter::Outcome::NotSupported : StopReporter::Outcome::AtRest);
        const QString message = w.statusBar()->currentMessage();
        QVERIFY2(message.contains(QLatin1String("Servo (CAN) #1: stopped")), qPrintable(message));
        QVERIFY2(message.contains(QLatin1String("Servo (Modbus) #1: has no stop command")), qPrintable(message));
        QVERIFY2(message.contains(QLatin1String("Shuoke")), qPrintable(message));
        QVERIFY2(!message.contains(QLatin1String("STOP sent to all drives")), qPrintable(message));
        // The demo servo runs only with its power stage on: the state says so.
        if (modbusRunning)
            QVERIFY(modbusState.enabled);
        w.connections()->disconnectAll();
    }

    // Issue #26: the STOP report in full at 1280 px: the status bar cuts it, so a "STOP
    // report…" button carries it whole as its tooltip and opens a window with one line per
    // drive; the servo-can line says that STOP switched its power stage off.
    void stopReportIsShownWholeAt1280()
    {
        MainWindow w;
        w.resize(1280, 720);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        DriveDirectory *dir = w.directory();
        QVERIFY(w.startDemo());
        QVERIFY(waitFor(
            [&] {
                int n = 0;
                for (int id : dir->connections())
                    for (int a : dir->drives(id))
                        n += dir->info(id, a).valid ? 1 : 0;
                return n == 3 && !w.connections()->isBusy();
            },
            20000));
        const int can = connectionOf(dir, Family::ServoCan);
        const int shuoke = connectionOf(dir, Family::Shuoke);
        int started = 0;
        for (int id : {can, shuoke}) {
            w.hub()->run(id, DemoBench::Address, [](Drive &d) { return d.setEnabled(true); });
            w.hub()->run(
                id, DemoBench::Address, [](Drive &d) { return d.moveRelative(100000000, 300); },
                [&started](const DriveResult &r) { started += r.ok() ? 1 : 0; });
        }
        QVERIFY(waitFor(
            [&] { return started == 2 && dir->info(can, 1).status.running && dir->info(can, 1).status.enabled; },
            10000));
        QToolButton *button = w.stopReportButton();
        QVERIFY(button);
        QVERIFY(!button->isVisible()); // nothing to report yet
        QSignalSpy finished(w.stopReporter(), &StopReporter::finished);
        w.stopAction()->trigger();
        QVERIFY(finished.wait(10000));
        QVERIFY(button->isVisible());
        QVERIFY(w.statusBar()->geometry().right() <= w.width());
        QVERIFY(w.statusBar()->rect().contains(button->geometry()));
        const QList<StopReporter::Line> lines = w.stopReporter()->lines();
        QCOMPARE(lines.size(), 3);
        QString canLine;
        for (const StopReporter::Line &l : lines) {
            const QString text = StopReporter::lineText(l);
            QVERIFY2(button->toolTip().contains(text), qPrintable(button->toolTip()));
            if (l.connectionId == can)
                canLine = text;
        }
        QVERIFY2(canLine.contains(QLatin1String("STOP switched its power stage off")), qPrintable(canLine));
        // The window: every line, nothing cut.
        QTest::mouseClick(button, Qt::LeftButton);
        StopReportView *view = w.stopReportView();
        QVERIFY(view);
        QVERIFY(QTest::qWaitForWindowExposed(view));
        for (const StopReporter::Line &l : lines)
            QVERIFY2(view->text().contains(StopReporter::lineText(l)), qPrintable(view->text()));
        QVERIFY(view->width() <= 1280 && view->height() <= 720);
        const QStringList cut = overflowcheck::problems(view);
        QVERIFY2(cut.isEmpty(), qPrintable(cut.join(QLatin1Char('\n'))));
        view->close();
        for (int id : {can, shuoke})
            w.hub()->run(id, DemoBench::Address, [](Drive &d) { return d.setEnabled(false); });
        w.connections()->disconnectAll();
    }

    // Issue #10: Demo → Inject alarm raises an alarm on a demo drive; the drive's alarm
    // history starts when it is found, not when its Alarms tab is first opened, and the
    // tab says what to check for a code the alarm table does not name.
    void demoAlarmIsInTheHistoryFromDiscovery()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        DriveDirectory *dir = w.directory();
        auto *demoMenu = w.findChild<DemoMenu *>();
        QVERIFY(demoMenu);
        demoMenu->rebuild();
        QCOMPARE(demoMenu->injectMenu()->actions().size(), 1); // "start the demo bench first"
        QVERIFY(!demoMenu->injectMenu()->actions().first()->isEnabled());
        QVERIFY(w.startDemo());
        QVERIFY(waitFor(
            [&] {
                int n = 0;
                for (int id : dir->connections())
                    for (int a : dir->drives(id))
                        n += dir->info(id, a).valid ? 1 : 0;
                return n == 3 && !w.connections()->isBusy();
            },
            20000));
        const int can = connectionOf(dir, Family::ServoCan);
        QVERIFY(can);
        if (w.workspace()->currentDrive().connectionId == can) // see the servo-can drive later
            w.busTree()->selectDrive(connectionOf(dir, Family::Shuoke), 1);
        QVERIFY(!w.workspace()->tabsFor(can, 1));

        demoMenu->rebuild();
        QAction *raise = nullptr;
        for (QAction *a : demoMenu->injectMenu()->actions())
            if (a->data().toString() == QLatin1String("servo-can"))
                raise = a;
        QVERIFY(raise);
        QVERIFY(raise->text().contains(QLatin1String("Alarm 12")));
        raise->trigger();
        QVERIFY2(waitFor([&] { return dir->info(can, 1).status.alarmCode == 12; }, 5000), "no alarm arrived");
        QTest::qWait(50); // later than the alarm by a measurable time
        const QDateTime opened = QDateTime::currentDateTime();
        w.busTree()->selectDrive(can, 1);
        w.workspace()->setPreferredPanel(QStringLiteral("alarms"));
        AlarmsPanel *alarms = nullptr;
        for (DrivePanel *p : w.workspace()->panelsFor(can, 1))
            if (auto *a = qobject_cast<AlarmsPanel *>(p))
                alarms = a;
        QVERIFY(alarms);
        QCOMPARE(alarms->currentCode(), 12);
        QCOMPARE(alarms->history().size(), 1);
        QVERIFY(alarms->history().first().time < opened);
        auto *remedy = alarms->findChild<QLabel *>(QStringLiteral("alarmRemedy"));
        QVERIFY(remedy->isVisible());
        QVERIFY2(remedy->text().contains(QLatin1String("knows no code 12")), qPrintable(remedy->text()));

        QVERIFY(demoMenu->injectAlarm(Family::ServoCan, 0));
        QVERIFY(waitFor([&] { return alarms->currentCode() == 0; }, 5000));
        QCOMPARE(alarms->history().size(), 2);
        w.connections()->disconnectAll();
    }

    // Issue #10: F1 opens a short user guide, bundled, in the UI language (also after a
    // switch); Help → Keyboard shortcuts lists the keys.
    void f1OpensTheUserGuideAndHelpListsTheShortcuts()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto *help = w.findChild<HelpActions *>();
        QVERIFY(help);
        QVERIFY(menuActionTexts(w, QStringLiteral("helpMenu")).contains(QStringLiteral("&User guide")));
        QTest::keyClick(&w, Qt::Key_F1);
        QTRY_VERIFY(help->guideDialog() && help->guideDialog()->isVisible());
        QVERIFY2(help->guideDialog()->guideText().contains(QLatin1String("a short user guide")),
                 qPrintable(help->guideDialog()->guideText().left(200)));
        QVERIFY2(help->guideDialog()->guideText().contains(QStringLiteral("Demo → Inject alarm")),
                 qPrintable(help->guideDialog()->guideText()));
        QVERIFY(w.languageManager()->apply(LanguageManager::Language::Chinese));
        QCoreApplication::sendPostedEvents();
        QVERIFY2(help->guideDialog()->guideText().contains(QStringLiteral("简明使用指南")),
                 qPrintable(help->guideDialog()->guideText().left(200)));
        QVERIFY(menuActionTexts(w, QStringLiteral("helpMenu")).contains(QStringLiteral("用户指南(&U)")));
        QVERIFY(w.languageManager()->apply(LanguageManager::Language::English));
        QCoreApplication::sendPostedEvents();
        QVERIFY(help->guideDialog()->guideText().contains(QLatin1String("a short user guide")));

        help->shortcutsAction()->trigger();
        QTRY_VERIFY(help->shortcutsDialog() && help->shortcutsDialog()->isVisible());
        QTableWidget *table = help->shortcutsDialog()->table();
        QStringList keys;
        for (int r = 0; r < table->rowCount(); ++r)
            keys << table->item(r, 0)->text();
        QVERIFY2(keys.contains(QStringLiteral("Esc / F12")), qPrintable(keys.join(QLatin1Char('|'))));
        QVERIFY(keys.contains(QStringLiteral("F1")));
        QVERIFY(keys.contains(QStringLiteral("Ctrl+K")));
    }

    void chineseTranslationLoadsAndSwitchesLive()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QCOMPARE(w.fileMenu()->title(), QStringLiteral("&File"));

        QVERIFY(w.languageManager()->apply(LanguageManager::Language::Chinese));
        QVERIFY(w.languageManager()->appTranslationLoaded());
        QCoreApplication::sendPostedEvents(); // LanguageChange is posted to top-level widgets
        QCOMPARE(w.fileMenu()->title(), QStringLiteral("文件(&F)"));
        QCOMPARE(menuTitles(w).at(2), QStringLiteral("语言(&L)"));
        QCOMPARE(w.stopAction()->text(), QStringLiteral("停止"));
        QVERIFY(w.windowTitle().contains(QStringLiteral("调试")));
        // The core's strings come from the same catalogue.
        QCOMPARE(QCoreApplication::translate("dd::DriveHub", "The connection is closed."),
                 QStringLiteral("连接已关闭。"));
        // Qt's own strings (standard buttons) when qt6-translations-l10n is installed.
        if (w.languageManager()->qtTranslationLoaded())
            QCOMPARE(QCoreApplication::translate("QPlatformTheme", "Cancel"), QStringLiteral("取消"));

        QVERIFY(w.languageManager()->apply(LanguageManager::Language::English));
        QCoreApplication::sendPostedEvents();
        QCOMPARE(w.fileMenu()->title(), QStringLiteral("&File"));
        QCOMPARE(w.stopAction()->text(), QStringLiteral("STOP"));
    }

    void languageMenuSwitchesAndRemembers()
    {
        {
            MainWindow w;
            QAction *chinese = nullptr;
            for (QAction *a : w.findChildren<QAction *>())
                if (a->data().toString() == QLatin1String("zh_CN"))
                    chinese = a;
            QVERIFY(chinese);
            chinese->trigger();
            QCoreApplication::sendPostedEvents();
            QVERIFY(chinese->isChecked());
            QCOMPARE(w.fileMenu()->title(), QStringLiteral("文件(&F)"));
            QCOMPARE(QSettings().value(QStringLiteral("language")).toString(), QStringLiteral("zh_CN"));
        }
        {
            MainWindow w; // a new window starts in the remembered language
            QCoreApplication::sendPostedEvents();
            QCOMPARE(w.fileMenu()->title(), QStringLiteral("文件(&F)"));
            w.languageManager()->apply(LanguageManager::Language::English);
            w.languageManager()->save();
        }
        QCOMPARE(LanguageManager::savedLanguage(), LanguageManager::Language::English);
    }

    void languageIds()
    {
        bool ok = false;
        QCOMPARE(LanguageManager::languageFromId(QStringLiteral("zh-CN"), &ok), LanguageManager::Language::Chinese);
        QVERIFY(ok);
        QCOMPARE(LanguageManager::languageFromId(QStringLiteral("en_US"), &ok), LanguageManager::Language::English);
        QVERIFY(ok);
        QCOMPARE(LanguageManager::languageFromId(QStringLiteral("system"), &ok), LanguageManager::Language::System);
        QVERIFY(ok);
        LanguageManager::languageFromId(QStringLiteral("klingon"), &ok);
        QVERIFY(!ok);
    }

    void recentFilesMenu()
    {
        MainWindow w;
        RecentFiles *recent = w.recentFiles();
        recent->clear();
        for (int i = 0; i < RecentFiles::MaxFiles + 2; ++i)
            recent->add(m_settingsDir.filePath(QStringLiteral("backup-%1.json").arg(i)));
        QCOMPARE(recent->files().size(), RecentFiles::MaxFiles);
        QVERIFY(recent->files().first().endsWith(QLatin1String("backup-9.json")));
        // Re-adding moves to the top instead of duplicating.
        recent->add(m_settingsDir.filePath(QStringLiteral("backup-5.json")));
        QCOMPARE(recent->files().size(), RecentFiles::MaxFiles);
        QVERIFY(recent->files().first().endsWith(QLatin1String("backup-5.json")));
        QCOMPARE(recent->files().count(m_settingsDir.filePath(QStringLiteral("backup-5.json"))), 1);

        QMenu *menu = nullptr;
        for (QAction *a : w.fileMenu()->actions())
            if (a->menu() && a->text() == QLatin1String("&Recent files"))
                menu = a->menu();
        QVERIFY(menu);
        QVERIFY(menu->actions().first()->text().contains(QLatin1String("backup-5.json")));
        QSignalSpy spy(recent, &RecentFiles::fileTriggered);
        menu->actions().first()->trigger();
        QCOMPARE(spy.count(), 1);
        QVERIFY(spy.first().first().toString().endsWith(QLatin1String("backup-5.json")));

        // Persisted.
        RecentFiles other;
        other.load();
        QCOMPARE(other.files(), recent->files());
        recent->clear();
    }

    void layoutIsSavedOnClose()
    {
        QSettings().remove(QStringLiteral("mainWindow"));
        {
            MainWindow w;
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            w.findChild<QDockWidget *>(QStringLiteral("busDock"))->hide();
            w.close();
        }
        QVERIFY(QSettings().contains(QStringLiteral("mainWindow/geometry")));
        MainWindow w;
        w.restoreLayout();
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(!w.findChild<QDockWidget *>(QStringLiteral("busDock"))->isVisible());
        QVERIFY(w.findChild<QToolBar *>(QStringLiteral("mainToolBar"))->isVisible());
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
