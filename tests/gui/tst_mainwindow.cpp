// The main window: construction, the STOP button and its shortcuts, live language switch,
// recent files, saved layout. Offscreen, with settings in a temporary directory.
#include "ui/bus/bustreewidget.h"
#include "ui/shell/languagemanager.h"
#include "ui/shell/mainwindow.h"
#include "ui/shell/recentfiles.h"
#include "ui/shell/stopaction.h"
#include "ui/workspace/driveworkspace.h"

#include <QApplication>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <QToolButton>

using namespace dd;

class TestMainWindow : public QObject
{
    Q_OBJECT

    QTemporaryDir m_settingsDir;

    static QStringList menuTitles(MainWindow &w)
    {
        QStringList out;
        for (QAction *a : w.menuBar()->actions())
            out << a->text();
        return out;
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
        QCOMPARE(menuTitles(w), QStringList({"&File", "&View", "&Language", "&Help"}));
        QVERIFY(w.windowTitle().contains(QLatin1String("DriveDesk")));
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
        // The status bar confirms it.
        QVERIFY(w.statusBar()->currentMessage().contains(QLatin1String("STOP")));
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
