// The whole window at a laptop's 1280×720, in English and in Chinese (issue #10): the demo
// bench, every tab of every family's drive shown in turn, and the dialogs the menus open —
// no visible widget cut (outside its parent, narrower than its text needs, a button's text
// cut, a wrapped label clipped or with an unbreakable piece wider than it), no horizontal
// scroll bar, no tab bar scrolling its titles, no tool bar folding buttons away
// (tests/gui/overflowcheck.h); the bus dock shows every drive's label and columns whole.
#include "core/drive/drivehub.h"
#include "tests/gui/overflowcheck.h"
#include "ui/bus/bustreewidget.h"
#include "ui/bus/connectdialog.h"
#include "ui/bus/connectioncontroller.h"
#include "ui/bus/drivedirectory.h"
#include "ui/compare/compareview.h"
#include "ui/help/shortcutsdialog.h"
#include "ui/help/userguidedialog.h"
#include "ui/report/recordaction.h"
#include "ui/report/recorddialog.h"
#include "ui/shell/aboutdialog.h"
#include "ui/shell/languagemanager.h"
#include "ui/shell/mainwindow.h"
#include "ui/workspace/drivepanel.h"
#include "ui/workspace/driveworkspace.h"

#include <QApplication>
#include <QHeaderView>
#include <QLabel>
#include <QLoggingCategory>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QStyle>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidgetItem>
#include <algorithm>

using namespace dd;

class TestOverflowWalk : public QObject
{
    Q_OBJECT

    QTemporaryDir m_settingsDir;

    template <typename Cond>
    static bool waitFor(Cond cond, int timeoutMs)
    {
        QDeadlineTimer deadline(timeoutMs);
        while (!cond() && !deadline.hasExpired())
            QTest::qWait(20);
        return cond();
    }

    // A dialog as it opens (its own size), then at the most a 1280×720 screen leaves it.
    static QStringList dialogProblems(QDialog *dialog)
    {
        QStringList out;
        dialog->show();
        QTest::qWait(20);
        const QSize need = dialog->minimumSizeHint();
        if (need.width() > 1280 || need.height() > 690)
            out << QStringLiteral("%1 needs %2×%3")
                       .arg(dialog->metaObject()->className())
                       .arg(need.width())
                       .arg(need.height());
        for (const QString &p : overflowcheck::problems(dialog))
            out << QString::fromLatin1(dialog->metaObject()->className()) + QStringLiteral(": ") + p;
        dialog->close();
        return out;
    }

    // Every drive row of the bus tree in view whole: its label not elided, its state,
    // position and firmware columns inside the viewport and as wide as their texts.
    static QStringList busDockProblems(MainWindow *w)
    {
        QStringList out;
        BusTreeWidget *tree = w->busTree();
        const int viewport = tree->viewport()->width();
        QWidget *dock = tree->window()->findChild<QWidget *>(QStringLiteral("busDock"));
        const QString where = QStringLiteral("bus dock %1 px wide (tree viewport %2 px, workspace minimum %3 px): ")
                                  .arg(dock ? dock->width() : -1)
                                  .arg(viewport)
                                  .arg(w->workspace()->minimumSizeHint().width());
        const QFontMetrics fm(tree->font());
        const int margin = tree->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, tree) * 2 + 2;
        for (int c = 0; c < tree->topLevelItemCount(); ++c) {
            QTreeWidgetItem *link = tree->topLevelItem(c);
            for (int d = 0; d < link->childCount(); ++d) {
                QTreeWidgetItem *drive = link->child(d);
                const int nameRoom = tree->header()->sectionSize(BusTreeWidget::NameColumn) - tree->indentation();
                const int nameNeeds = fm.horizontalAdvance(drive->text(BusTreeWidget::NameColumn)) + margin;
                if (nameRoom < nameNeeds)
                    out << where
                            + QStringLiteral("label \"%1\" elided (%2 px for %3)")
                                  .arg(drive->text(BusTreeWidget::NameColumn))
                                  .arg(nameRoom)
                                  .arg(nameNeeds);
                for (int col : {int(BusTreeWidget::StateColumn), int(BusTreeWidget::PositionColumn),
                                int(BusTreeWidget::FirmwareColumn)}) {
                    const int right = tree->header()->sectionViewportPosition(col) + tree->header()->sectionSize(col);
                    if (right > viewport)
                        out << where
                                + QStringLiteral("column %1 (\"%2\") ends at %3 px, beyond the view")
                                      .arg(col)
                                      .arg(drive->text(col))
                                      .arg(right);
                }
            }
        }
        return out;
    }

private slots:
    void initTestCase()
    {
        QLoggingCategory::setFilterRules(QStringLiteral("drivedesk.*.debug=false"));
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_settingsDir.isValid());
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_settingsDir.path());
        QCoreApplication::setOrganizationName(QStringLiteral("DriveDeskTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_overflowwalk"));
    }

    // The check itself sees cut texts: a button squeezed below its text (its layout may
    // ignore its size hint), a wrapped label lower than its lines, an unbreakable checksum
    // wider than its wrapped label; and nothing in a window that fits.
    void theCheckSeesCutTexts()
    {
        QWidget top;
        top.resize(400, 200);
        auto *button = new QPushButton(QStringLiteral("Export the whole recording as CSV"), &top);
        button->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
        button->setGeometry(0, 0, 60, 30);
        auto *wrapped = new QLabel(QStringLiteral("A long sentence that needs three or four lines at this width."),
                                   &top);
        wrapped->setWordWrap(true);
        wrapped->setGeometry(0, 40, 120, 18);
        auto *path = new QLabel(QStringLiteral("SHA-256 6f81970026c0063a636545b09fd4a8b7aef9c120144a14be"), &top);
        path->setWordWrap(true);
        path->setGeometry(0, 100, 150, 120);
        top.show();
        QVERIFY(QTest::qWaitForWindowExposed(&top));
        const QStringList found = overflowcheck::problems(&top);
        const auto has = [&found](const QString &what) {
            return std::any_of(found.cbegin(), found.cend(), [&what](const QString &p) { return p.startsWith(what); });
        };
        QVERIFY2(has(QStringLiteral("button text cut")), qPrintable(found.join(u'\n')));
        QVERIFY2(has(QStringLiteral("wrapped text clipped")), qPrintable(found.join(u'\n')));
        QVERIFY2(has(QStringLiteral("unbreakable \"6f81970026")), qPrintable(found.join(u'\n')));
        button->setGeometry(0, 0, 380, 30);
        wrapped->setGeometry(0, 40, 380, 40);
        path->setGeometry(0, 100, 395, 60);
        QVERIFY2(overflowcheck::problems(&top).isEmpty(), qPrintable(overflowcheck::problems(&top).join(u'\n')));
    }

    void nothingIsCutAt1280x720_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }

    void nothingIsCutAt1280x720()
    {
        QFETCH(QString, language);
        LanguageManager languages;
        QVERIFY(languages.apply(LanguageManager::languageFromId(language)));
        MainWindow w(&languages);
        w.resize(1280, 720);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QCOMPARE(w.size(), QSize(1280, 720)); // its minimum fits
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

        QStringList problems;
        for (int id : dir->connections()) {
            w.busTree()->selectDrive(id, 1);
            QTabWidget *tabs = w.workspace()->tabsFor(id, 1);
            QVERIFY(tabs);
            const QString family = familyId(dir->connectionSettings(id).family);
            for (int i = 0; i < tabs->count(); ++i) {
                tabs->setCurrentIndex(i);
                QTest::qWait(150); // what each tab fills in when shown (reads, polls)
                for (const QString &p : overflowcheck::problems(&w))
                    problems << QStringLiteral("%1 / %2: %3").arg(family, tabs->tabText(i), p);
            }
        }
        problems << dialogProblems(new ConnectDialog(&w));
        problems << dialogProblems(new AboutDialog(&w));
        problems << dialogProblems(new UserGuideDialog(&w));
        problems << dialogProblems(new ShortcutsDialog(&w));
        problems << dialogProblems(new CompareView(dir, &w));
        if (auto *record = w.findChild<RecordAction *>())
            problems << dialogProblems(new RecordDialog(dir, record->session(), &w));
        problems.removeDuplicates();
        for (const QString &p : std::as_const(problems))
            qWarning("%s", qPrintable(p));
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));

        // The bus dock shows each drive's label, state, position and firmware whole, without
        // sideways scrolling: the tab pages' minimum widths left it room (every tab of every
        // drive has been shown above, so the workspace's minimum is the widest page's).
        QApplication::processEvents();
        QStringList dock = busDockProblems(&w);
        for (const QString &p : std::as_const(dock))
            qWarning("%s", qPrintable(p));
        QVERIFY2(dock.isEmpty(), qPrintable(dock.join(QLatin1Char('\n'))));
        w.connections()->disconnectAll();
    }
};

QTEST_MAIN(TestOverflowWalk)
#include "tst_overflowwalk.moc"
