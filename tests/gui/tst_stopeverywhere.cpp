// STOP from every window (issue #26, item 1): on the demo bench, with a servo-can and a shuoke
// drive moving, every dialog and message box DriveDesk can show is opened in turn (from its
// menu where it has one, the EE-operation confirmation from the EE tab, the others made as the
// application makes them), and F12 pressed inside it must stop every drive — the drives report
// the axis at rest, the STOP report lists every drive. Each dialog carries a STOP button that
// triggers the same STOP; Esc is STOP and then closes what it closes (docs/gui.md). The same
// from an open menu and a cell editor. Quitting with a drive enabled or moving asks first and
// STOPs on "STOP and quit".
#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/restorereport.h"
#include "core/link/serialaccess.h"
#include "core/params/parameterdictionary.h"
#include "sim/bench/demobench.h"
#include "tests/support/requiretool.h"
#include "ui/bus/bustreewidget.h"
#include "ui/bus/connectioncontroller.h"
#include "ui/bus/drivedirectory.h"
#include "ui/bus/serialaccessdialog.h"
#include "ui/compare/compareview.h"
#include "ui/fleet/fleetapplydialog.h"
#include "ui/panels/backup/restorereportdialog.h"
#include "ui/report/recordaction.h"
#include "ui/report/recorddialog.h"
#include "ui/shell/mainwindow.h"
#include "ui/shell/stopaction.h"
#include "ui/shell/stopguard.h"
#include "ui/shell/stopreporter.h"
#include "ui/workspace/drivepanel.h"
#include "ui/workspace/driveworkspace.h"

#include <QAbstractItemView>
#include <QApplication>
#include <QCanBus>
#include <QDialog>
#include <QDirIterator>
#include <QFileDialog>
#include <QLoggingCategory>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QRegularExpression>
#include <QSet>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <functional>
#include <memory>

using namespace dd;

namespace {

template <typename Cond>
bool pollUntil(Cond cond, int timeoutMs)
{
    QDeadlineTimer deadline(timeoutMs);
    while (!cond() && !deadline.hasExpired())
        QTest::qWait(20);
    return cond();
}

int stopConnectionOf(DriveDirectory *dir, Family f)
{
    for (int id : dir->connections())
        if (dir->connectionSettings(id).family == f)
            return id;
    return 0;
}

QList<QWidget *> visibleWindows()
{
    QList<QWidget *> out;
    for (QWidget *w : QApplication::topLevelWidgets())
        if (w->isVisible() && w->isWindow())
            out << w;
    return out;
}

// A dialog (or menu) shown since `before`.
QWidget *newWindow(const QList<QWidget *> &before)
{
    for (QWidget *w : visibleWindows())
        if (!before.contains(w) && (qobject_cast<QDialog *>(w) || qobject_cast<QMenu *>(w)))
            return w;
    return nullptr;
}

} // namespace

class TestStopEverywhere : public QObject
{
    Q_OBJECT

    QTemporaryDir m_settingsDir;
    std::unique_ptr<MainWindow> m_window;
    int m_can = 0;
    int m_shuoke = 0;
    int m_modbus = 0;
    QStringList m_problems;        // collected inside nested event loops (QVERIFY cannot leave them)
    QSet<QString> m_walkedDialogs; // class names (without namespace) of the dialogs visited

    MainWindow &w() { return *m_window; }

    // Enables the servo-can and the shuoke drive and starts a long move on each; true when
    // both report motion.
    bool startMotion()
    {
        int started = 0;
        for (int id : {m_can, m_shuoke}) {
            w().hub()->run(id, DemoBench::Address, [](Drive &d) { return d.setEnabled(true); });
            w().hub()->run(
                id, DemoBench::Address, [](Drive &d) { return d.moveRelative(100000000, 300); },
                [&started](const DriveResult &r) { started += r.ok() ? 1 : 0; });
        }
        DriveDirectory *dir = w().directory();
        return pollUntil(
            [&] {
                return started == 2 && dir->info(m_can, DemoBench::Address).status.running
                    && dir->info(m_shuoke, DemoBench::Address).status.running;
            },
            20000);
    }

    // After a STOP: the report has every drive, the two that have a stop command report
    // their axis at rest (StopReporter reads each drive's own state).
    QString stopReachedEveryDrive(QSignalSpy &finished)
    {
        if (finished.isEmpty() && !finished.wait(20000))
            return QStringLiteral("the STOP report never finished (no STOP?)");
        const QList<StopReporter::Line> lines = w().stopReporter()->lines();
        if (lines.size() != 3)
            return QStringLiteral("the STOP report has %1 drives, not 3").arg(lines.size());
        for (const StopReporter::Line &l : lines) {
            const bool ok = l.family == Family::ServoModbus
                ? (l.outcome == StopReporter::Outcome::AtRest || l.outcome == StopReporter::Outcome::NotSupported)
                : l.outcome == StopReporter::Outcome::Stopped;
            if (!ok)
                return QStringLiteral("not stopped: %1").arg(StopReporter::lineText(l));
        }
        return QString();
    }

    // Starts motion, does `press` (a STOP from somewhere), proves every drive stopped.
    QString proveStop(const std::function<void()> &press)
    {
        if (!startMotion())
            return QStringLiteral("the drives did not start moving");
        QSignalSpy finished(w().stopReporter(), &StopReporter::finished);
        press();
        return stopReachedEveryDrive(finished);
    }

    // Runs `open` (which may block in a dialog's exec()); once a new dialog or menu is shown,
    // runs `inside` on it, then closes it if it is still open. Problems go to m_problems,
    // named `what`.
    void whileOpen(const QString &what, const std::function<void()> &open, const std::function<void(QWidget *)> &inside)
    {
        const QList<QWidget *> before = visibleWindows();
        bool done = false;
        QTimer poll;
        poll.setInterval(20);
        QDeadlineTimer deadline(20000);
        connect(&poll, &QTimer::timeout, this, [&] {
            QPointer<QWidget> shown = newWindow(before);
            if (!shown && !deadline.hasExpired())
                return;
            poll.stop();
            if (!shown) {
                m_problems << what + QStringLiteral(": no dialog opened");
            } else {
                if (shown->inherits("QDialog"))
                    m_walkedDialogs
                        << QString::fromLatin1(shown->metaObject()->className()).section(QStringLiteral("::"), -1);
                if (!QTest::qWaitForWindowExposed(shown))
                    m_problems << what + QStringLiteral(": not exposed");
                inside(shown);
                if (shown && shown->isVisible()) {
                    if (auto *d = qobject_cast<QDialog *>(shown.data()))
                        d->reject();
                    else
                        shown->close();
                }
            }
            done = true;
        });
        poll.start();
        open();
        if (!pollUntil([&] { return done; }, 30000))
            m_problems << what + QStringLiteral(": the check did not finish");
    }

    // Inside a dialog: F12 at its focus widget stops every drive; its STOP button is there,
    // above its contents, and triggers STOP.
    std::function<void(QWidget *)> stopFromDialog(const QString &what)
    {
        return [this, what](QWidget *dialog) {
            QWidget *focus = dialog->focusWidget() ? dialog->focusWidget() : dialog;
            const QString f12 = proveStop([focus] { QTest::keyClick(focus, Qt::Key_F12); });
            if (!f12.isEmpty())
                m_problems << QStringLiteral("%1 (%2), F12: %3").arg(what, dialog->metaObject()->className(), f12);
            if (!dialog->isVisible())
                m_problems << what + QStringLiteral(": F12 closed the dialog");
            auto *button = dialog->findChild<QToolButton *>(QLatin1String(StopGuard::DialogStopButtonName));
            if (!button || !button->isVisible()) {
                m_problems << what + QStringLiteral(": no STOP button in the dialog");
                return;
            }
            // In its strip: above the dialog's own contents, inside the dialog.
            if (button->geometry().bottom() >= dialog->contentsRect().top()
                || !dialog->rect().contains(button->geometry()))
                m_problems << what + QStringLiteral(": the STOP button overlaps the dialog's contents");
            QSignalSpy triggered(w().stopAction(), &QAction::triggered);
            QTest::mouseClick(button, Qt::LeftButton);
            if (triggered.count() != 1)
                m_problems << what + QStringLiteral(": its STOP button did not trigger STOP");
            if (!pollUntil([this] { return !w().stopReporter()->isRunning(); }, 10000))
                m_problems << what + QStringLiteral(": the STOP report of the button never finished");
        };
    }

    QAction *menuAction(const QString &menuName, const QString &actionName)
    {
        auto *menu = w().findChild<QMenu *>(menuName);
        if (!menu)
            return nullptr;
        for (QAction *a : menu->actions())
            if (a->objectName() == actionName)
                return a;
        return nullptr;
    }

    DrivePanel *panel(int id, const QString &panelId)
    {
        for (DrivePanel *p : w().workspace()->panelsFor(id, DemoBench::Address))
            if (p->panelId() == panelId)
                return p;
        return nullptr;
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
        QCoreApplication::setApplicationName(QStringLiteral("tst_stopeverywhere"));
        QSettings().setValue(QStringLiteral("language"), QStringLiteral("en"));
        DD_REQUIRE_TOOL(QCanBus::instance()->plugins().contains(QLatin1String("virtualcan")),
                        "Qt's virtualcan plugin is not installed");
        m_window = std::make_unique<MainWindow>();
        w().resize(1280, 720);
        w().show();
        QVERIFY(QTest::qWaitForWindowExposed(&w()));
        DriveDirectory *dir = w().directory();
        QVERIFY(w().startDemo());
        QVERIFY(pollUntil(
            [&] {
                int n = 0;
                for (int id : dir->connections())
                    for (int a : dir->drives(id))
                        n += dir->info(id, a).valid ? 1 : 0;
                return n == 3 && !w().connections()->isBusy();
            },
            20000));
        m_can = stopConnectionOf(dir, Family::ServoCan);
        m_shuoke = stopConnectionOf(dir, Family::Shuoke);
        m_modbus = stopConnectionOf(dir, Family::ServoModbus);
        QVERIFY(m_can && m_shuoke && m_modbus);
    }

    void cleanupTestCase()
    {
        if (!m_window)
            return;
        // Nothing enabled any more: quitting does not ask.
        for (int id : {m_can, m_shuoke})
            w().hub()->run(id, DemoBench::Address, [](Drive &d) { return d.setEnabled(false); });
        m_window->connections()->disconnectAll();
        m_window.reset();
    }

    void init() { m_problems.clear(); }

    // The main window itself, nothing open: F12 and Esc.
    void stopFromTheMainWindow()
    {
        QApplication::setActiveWindow(&w());
        for (Qt::Key key : {Qt::Key_F12, Qt::Key_Escape}) {
            const QString p = proveStop([this, key] { QTest::keyClick(w().busTree(), key); });
            QVERIFY2(p.isEmpty(), qPrintable(p));
        }
    }

    // Every dialog the menus open, in each of them F12 and the dialog's STOP button.
    void stopFromEveryMenuDialog()
    {
        w().busTree()->selectDrive(m_modbus, DemoBench::Address); // File → Load dictionary needs a drive
        QTRY_VERIFY(w().workspace()->currentDrive().connectionId == m_modbus);
        const QList<QPair<QString, QString>> actions = {
            {QStringLiteral("fileMenu"), QStringLiteral("connectAction")},
            {QStringLiteral("fileMenu"), QStringLiteral("commissioningRecordAction")},
            {QStringLiteral("fileMenu"), QStringLiteral("loadDictionaryAction")},
            {QStringLiteral("viewMenu"), QStringLiteral("compareAction")},
            {QStringLiteral("helpMenu"), QStringLiteral("userGuideAction")},
            {QStringLiteral("helpMenu"), QStringLiteral("shortcutsAction")},
        };
        for (const auto &[menu, name] : actions) {
            QAction *a = menuAction(menu, name);
            QVERIFY2(a, qPrintable(name));
            whileOpen(
                name, [a] { a->trigger(); }, stopFromDialog(name));
        }
        // Help → About and About Qt. (By name: this loop once took "the first two of the Help
        // menu", which the user guide and the shortcuts had become, and About was never
        // walked; everyDialogOfTheGuiWasWalked found it.)
        for (const QString &name : {QStringLiteral("aboutAction"), QStringLiteral("aboutQtAction")}) {
            QAction *a = menuAction(QStringLiteral("helpMenu"), name);
            QVERIFY2(a, qPrintable(name));
            whileOpen(
                a->text(), [a] { a->trigger(); }, stopFromDialog(a->text()));
        }
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
    }

    // The EE-operation confirmation (a modal message box), opened from the EE tab.
    void stopFromTheEeConfirmation()
    {
        w().busTree()->selectDrive(m_modbus, DemoBench::Address);
        DrivePanel *ee = panel(m_modbus, QStringLiteral("ee"));
        QVERIFY(ee);
        w().workspace()->tabsFor(m_modbus, DemoBench::Address)->setCurrentWidget(ee);
        auto *factory = ee->findChild<QPushButton *>(
            QStringLiteral("eeButton%1").arg(int(EeOperation::FactoryDefaults)));
        QVERIFY(factory);
        QTRY_VERIFY(factory->isEnabled());
        whileOpen(
            QStringLiteral("EE confirmation"), [factory] { factory->click(); },
            stopFromDialog(QStringLiteral("EE confirmation")));
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
    }

    // The dialogs shown on an event (a serial port refused, a restore done, a fleet apply),
    // message boxes and the file dialogs, made as the application makes them.
    void stopFromEveryOtherDialog()
    {
        QWidget *win = &w();
        DriveDirectory *dir = w().directory();
        const QList<QPair<QString, std::function<void()>>> dialogs = {
            {QStringLiteral("SerialAccessDialog"),
             [win] {
                 SerialAccessProblem p;
                 p.port = QStringLiteral("/dev/ttyUSB0");
                 p.group = QStringLiteral("dialout");
                 auto *d = new SerialAccessDialog(p, win);
                 d->setAttribute(Qt::WA_DeleteOnClose);
                 d->open();
             }},
            {QStringLiteral("RestoreReportDialog"),
             [win] {
                 auto *d = new RestoreReportDialog(RestoreReport{}, ParameterDictionary::bundled(Family::ServoModbus),
                                                   QStringLiteral("drive.ddbackup"), win);
                 d->setAttribute(Qt::WA_DeleteOnClose);
                 d->open();
             }},
            {QStringLiteral("FleetApplyDialog"),
             [win, dir, this] {
                 auto *d = new FleetApplyDialog(dir, m_modbus, {DemoBench::Address}, win);
                 d->setAttribute(Qt::WA_DeleteOnClose);
                 d->open();
             }},
            {QStringLiteral("CompareView"),
             [win, dir] {
                 auto *d = new CompareView(dir, win);
                 d->setAttribute(Qt::WA_DeleteOnClose);
                 d->show();
             }},
            {QStringLiteral("StopReportView"), [this] { w().showStopReport(); }},
            {QStringLiteral("warning message box"),
             [win] { QMessageBox::warning(win, QStringLiteral("Demo bench"), QStringLiteral("It could not start.")); }},
            {QStringLiteral("question message box"),
             [win] {
                 QMessageBox box(QMessageBox::Warning, QStringLiteral("Change communication settings?"),
                                 QStringLiteral("Write them?"), QMessageBox::Yes | QMessageBox::Cancel, win);
                 box.exec();
             }},
            {QStringLiteral("open file dialog"),
             [win] { QFileDialog::getOpenFileName(win, QStringLiteral("Open backup"), QString()); }},
            {QStringLiteral("save file dialog"),
             [win] { QFileDialog::getSaveFileName(win, QStringLiteral("Save backup"), QString()); }},
        };
        for (const auto &[name, open] : dialogs)
            whileOpen(name, open, stopFromDialog(name));
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
    }

    // Esc in a dialog: STOP, and the dialog closes as Esc closes it.
    void escInADialogStopsAndCloses()
    {
        QAction *about = menuAction(QStringLiteral("helpMenu"), QStringLiteral("aboutAction"));
        QVERIFY(about);
        whileOpen(
            QStringLiteral("About"), [about] { about->trigger(); },
            [this](QWidget *dialog) {
                // About deletes itself once closed, and proveStop() runs the event loop after
                // the key: everything of it is watched through guards taken before the key.
                const QPointer<QWidget> guard(dialog);
                const QPointer<QWidget> focus(dialog->focusWidget() ? dialog->focusWidget() : dialog);
                const QString p = proveStop([focus] {
                    QTest::keyPress(focus, Qt::Key_Escape);
                    if (focus)
                        QTest::keyRelease(focus, Qt::Key_Escape);
                });
                if (!p.isEmpty())
                    m_problems << QStringLiteral("About, Esc: ") + p;
                if (!pollUntil([guard] { return !guard || !guard->isVisible(); }, 5000))
                    m_problems << QStringLiteral("About: Esc did not close it");
            });
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
    }

    // An open menu (File, and the bus tree's right-click menu) and a cell editor.
    void stopFromAnOpenMenuAndACellEditor()
    {
        auto *file = w().findChild<QMenu *>(QStringLiteral("fileMenu"));
        QVERIFY(file);
        whileOpen(
            QStringLiteral("File menu"), [file, this] { file->popup(w().mapToGlobal(QPoint(10, 10))); },
            [this](QWidget *menu) {
                const QString p = proveStop([menu] { QTest::keyClick(menu, Qt::Key_F12); });
                if (!p.isEmpty())
                    m_problems << QStringLiteral("File menu, F12: ") + p;
            });

        w().busTree()->selectDrive(m_modbus, DemoBench::Address);
        DrivePanel *parameters = panel(m_modbus, QStringLiteral("parameters"));
        QVERIFY(parameters);
        w().workspace()->tabsFor(m_modbus, DemoBench::Address)->setCurrentWidget(parameters);
        auto *view = parameters->findChild<QAbstractItemView *>();
        QVERIFY(view);
        QTRY_VERIFY_WITH_TIMEOUT(view->model()->rowCount() > 0, 10000);
        // The first editable cell.
        QModelIndex editable;
        for (int r = 0; r < view->model()->rowCount() && !editable.isValid(); ++r)
            for (int c = 0; c < view->model()->columnCount() && !editable.isValid(); ++c) {
                const QModelIndex i = view->model()->index(r, c);
                if (i.flags().testFlag(Qt::ItemIsEditable))
                    editable = i;
            }
        QVERIFY(editable.isValid());
        view->setCurrentIndex(editable);
        view->edit(editable);
        QWidget *editor = view->indexWidget(editable);
        if (!editor)
            editor = QApplication::focusWidget();
        QVERIFY(editor);
        QPointer<QWidget> open(editor);
        QVERIFY(editor->isVisible());
        QString p = proveStop([editor] { QTest::keyClick(editor, Qt::Key_F12); });
        QVERIFY2(p.isEmpty(), qPrintable(QStringLiteral("cell editor, F12: ") + p));
        QVERIFY(open && open->isVisible()); // F12 is only STOP
        // Esc: STOP, and the edit is cancelled as Esc cancels it.
        p = proveStop([editor] { QTest::keyClick(editor, Qt::Key_Escape); });
        QVERIFY2(p.isEmpty(), qPrintable(QStringLiteral("cell editor, Esc: ") + p));
        QTRY_VERIFY(!open || !open->isVisible());
        QVERIFY2(m_problems.isEmpty(), qPrintable(m_problems.join(QLatin1Char('\n'))));
    }

    // Quitting with drives enabled or moving: asked first; Cancel leaves everything as it
    // is, "STOP and quit" stops every drive and closes the window.
    void quittingAsksAndStops()
    {
        QVERIFY(startMotion());
        bool asked = false;
        QString text;
        const auto answer = [&](const QString &button) {
            QTimer::singleShot(0, this, [&, button] {
                QTRY_VERIFY_WITH_TIMEOUT(QApplication::activeModalWidget(), 10000);
                auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
                QVERIFY(box);
                asked = box->objectName() == QLatin1String("quitConfirmation");
                text = box->text();
                if (button.isEmpty()) {
                    box->reject();
                    return;
                }
                auto *b = box->findChild<QPushButton *>(button);
                QVERIFY(b);
                b->click();
            });
        };
        answer(QString()); // Cancel
        QVERIFY(!w().close());
        QVERIFY(asked);
        QVERIFY2(text.contains(QLatin1String("is moving")), qPrintable(text));
        QVERIFY(w().isVisible());
        QVERIFY(w().directory()->info(m_can, DemoBench::Address).status.running);

        asked = false;
        QSignalSpy finished(w().stopReporter(), &StopReporter::finished);
        answer(QStringLiteral("stopAndQuit"));
        QVERIFY(w().close());
        QVERIFY(asked);
        QVERIFY(!w().isVisible());
        const QString p = stopReachedEveryDrive(finished);
        QVERIFY2(p.isEmpty(), qPrintable(p));
        w().show(); // for cleanupTestCase
    }

    // Last, after the walks above: every dialog class of the GUI (ui/, `class X : public
    // QDialog`) was opened by one of them. A new dialog that no walk reaches fails here until
    // it is added to stopFromEveryMenuDialog (through its menu) or stopFromEveryOtherDialog.
    void everyDialogOfTheGuiWasWalked()
    {
        if (m_walkedDialogs.isEmpty())
            QSKIP("needs the walks of this file before it (run the whole file)");
        const QDir ui(qEnvironmentVariable("DRIVEDESK_SOURCE_DIR") + QStringLiteral("/ui"));
        QVERIFY2(ui.exists(), qPrintable(ui.path()));
        static const QRegularExpression declaration(QStringLiteral("class (\\w+) : public QDialog\\b"));
        QStringList declared, missing;
        QDirIterator it(ui.path(), {QStringLiteral("*.h")}, QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            QFile f(it.next());
            QVERIFY(f.open(QIODevice::ReadOnly));
            auto m = declaration.globalMatch(QString::fromUtf8(f.readAll()));
            while (m.hasNext())
                declared << m.next().captured(1);
        }
        QVERIFY2(declared.size() >= 10, qPrintable(declared.join(QLatin1Char(' ')))); // the scan found them
        for (const QString &name : declared)
            if (!m_walkedDialogs.contains(name))
                missing << name;
        QVERIFY2(missing.isEmpty(),
                 qPrintable(QStringLiteral("no walk opened: ") + missing.join(QStringLiteral(", "))));
    }
};

QTEST_MAIN(TestStopEverywhere)
#include "tst_stopeverywhere.moc"
