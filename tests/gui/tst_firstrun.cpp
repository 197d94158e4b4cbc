// First run and desktop integration in the GUI: the connect dialog without any serial port
// offers the demo bench; the "permission denied" dialog copies the command that fixes it;
// About names the version, Qt and the licence (also in Chinese); `drivedesk FILE` opens a
// backup in the first drive's Backup tab.
#include "core/link/serialaccess.h"
#include "ui/bus/connectdialog.h"
#include "ui/bus/connectioncontroller.h"
#include "ui/bus/serialaccessdialog.h"
#include "ui/shell/aboutdialog.h"
#include "ui/shell/commandlinefile.h"
#include "ui/shell/languagemanager.h"
#include "ui/shell/mainwindow.h"
#include "ui/shell/recentfiles.h"
#include "ui/workspace/drivepanel.h"
#include "ui/workspace/driveworkspace.h"

#include <QApplication>
#include <QCanBus>
#include <QClipboard>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QLoggingCategory>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace dd;

class TestFirstRun : public QObject
{
    Q_OBJECT

    QTemporaryDir m_settingsDir;

    static SerialAccessProblem dialoutProblem()
    {
        SerialAccessProblem p;
        p.port = QStringLiteral("/dev/ttyUSB0");
        p.group = QStringLiteral("dialout");
        return p;
    }

    static QString currentPanelId(MainWindow &w)
    {
        auto *tabs = qobject_cast<QTabWidget *>(w.workspace()->currentWidget());
        auto *panel = tabs ? qobject_cast<DrivePanel *>(tabs->currentWidget()) : nullptr;
        return panel ? panel->panelId() : QString();
    }

private slots:
    void initTestCase()
    {
        QLoggingCategory::setFilterRules(QStringLiteral("qt.canbus.plugins.virtualcan.info=false\n"
                                                        "drivedesk.*.debug=false"));
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_settingsDir.isValid());
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
        QCoreApplication::setOrganizationName(QStringLiteral("DriveDeskTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_firstrun"));
        QSettings().setValue(QStringLiteral("language"), QStringLiteral("en"));
    }

    void connectDialogOffersDemoWithoutPorts()
    {
        ConnectDialog dialog;
        dialog.setPorts({});
        dialog.show();
        dialog.setPorts({}); // as after the watcher's first look, whatever this machine has
        QVERIFY(dialog.offersDemo());
        auto *hint = dialog.findChild<QWidget *>(QStringLiteral("noPortsHint"));
        QVERIFY(hint && hint->isVisible());
        QVERIFY(hint->findChild<QLabel *>()->text().contains(QLatin1String("No serial port was found")));
        auto *demo = dialog.findChild<QPushButton *>(QStringLiteral("startDemoButton"));
        QVERIFY(demo && demo->isVisible());
        QSignalSpy finished(&dialog, &QDialog::finished);
        demo->click();
        QCOMPARE(finished.size(), 1);
        QCOMPARE(dialog.result(), ConnectDialog::DemoRequested);

        // A port appears: the hint goes.
        SerialPortEntry e;
        e.path = QStringLiteral("/dev/ttyUSB0");
        dialog.setPorts({e});
        QVERIFY(!dialog.offersDemo());
        QCOMPARE(dialog.portCombo()->count(), 1);
    }

    void serialAccessDialogCopiesTheCommand()
    {
        SerialAccessDialog dialog(dialoutProblem());
        dialog.show();
        auto *command = dialog.findChild<QLineEdit *>(QStringLiteral("serialAccessCommand"));
        QVERIFY(command && command->isVisible());
        QCOMPARE(command->text(), QStringLiteral("sudo usermod -aG dialout $USER"));
        QVERIFY(dialog.findChild<QLabel *>() != nullptr);
        const QString all = dialog.findChildren<QLabel *>().last()->text();
        QVERIFY2(all.contains(QLatin1String("log out and log in again")), qPrintable(all));
        QGuiApplication::clipboard()->clear();
        QVERIFY(dialog.copyButton()->isVisible());
        dialog.copyButton()->click();
        QCOMPARE(QGuiApplication::clipboard()->text(), QStringLiteral("sudo usermod -aG dialout $USER"));
    }

    void serialAccessAlreadyMemberOnlyNeedsANewLogin()
    {
        SerialAccessProblem p = dialoutProblem();
        p.alreadyMember = true;
        SerialAccessDialog dialog(p);
        dialog.show();
        QVERIFY(!dialog.copyButton()->isVisible());
        QVERIFY(p.message().contains(QLatin1String("Log out and log in again")));
        QVERIFY(!p.message().contains(QLatin1String("usermod")));
    }

    void serialAccessMessageNamesPortGroupAndCommand()
    {
        const QString m = dialoutProblem().message();
        QVERIFY2(m.contains(QLatin1String("/dev/ttyUSB0")), qPrintable(m));
        QVERIFY2(m.contains(QLatin1String("'dialout'")), qPrintable(m));
        QVERIFY2(m.contains(QLatin1String("\n    sudo usermod -aG dialout $USER\n")), qPrintable(m));
        SerialAccessProblem noGroup;
        noGroup.port = QStringLiteral("/dev/ttyS0");
        QVERIFY(noGroup.command().isEmpty());
        QVERIFY(noGroup.message().contains(QLatin1String("administrator")));
    }

    void aboutNamesVersionQtAndLicence()
    {
        LanguageManager language;
        QVERIFY(language.apply(LanguageManager::Language::English));
        AboutDialog about;
        about.show();
        QVERIFY(about.text().contains(QStringLiteral("DriveDesk " DRIVEDESK_VERSION)));
        QVERIFY(about.text().contains(QStringLiteral("Qt ") + QString::fromLatin1(qVersion())));
        QVERIFY(about.text().contains(QLatin1String("GNU General Public License, version 3")));
        // Live language switch: the open dialog follows.
        QVERIFY(language.apply(LanguageManager::Language::Chinese));
        QTRY_VERIFY2(about.text().contains(QStringLiteral("GNU 通用公共许可证")), qPrintable(about.text()));
        QCOMPARE(about.windowTitle(), QStringLiteral("关于 DriveDesk"));
        QVERIFY(about.text().contains(QStringLiteral(DRIVEDESK_VERSION)));
        QVERIFY(language.apply(LanguageManager::Language::English));
    }

    void commandLineFileOpensInTheFirstDrive()
    {
        if (!QCanBus::instance()->plugins().contains(QLatin1String("virtualcan")))
            QSKIP("Qt's virtualcan plugin is not installed (the demo bench needs it)");
        const QString backup = QDir(qEnvironmentVariable("DRIVEDESK_SOURCE_DIR"))
                                   .filePath(QStringLiteral("tests/data/backup/good/servo-modbus.json"));
        QVERIFY2(QFileInfo::exists(backup), qPrintable(backup));
        QVERIFY(CommandLineFile::checkReadable(backup).isEmpty());
        QVERIFY(!CommandLineFile::checkReadable(m_settingsDir.filePath(QStringLiteral("missing.json"))).isEmpty());

        MainWindow w;
        w.setPreferredFamily(Family::ServoModbus);
        w.show();
        new CommandLineFile(&w, backup);
        QVERIFY(w.recentFiles()->files().contains(QFileInfo(backup).absoluteFilePath()));
        QVERIFY2(w.statusBar()->currentMessage().contains(QLatin1String("when a drive is selected")),
                 qPrintable(w.statusBar()->currentMessage()));
        QVERIFY(w.startDemo());
        QTRY_COMPARE_WITH_TIMEOUT(currentPanelId(w), QStringLiteral("backup"), 20000);
    }
};

QTEST_MAIN(TestFirstRun)
#include "tst_firstrun.moc"
