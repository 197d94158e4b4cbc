// Live language switch (issue #10 item 5): the demo bench with every drive's tabs visited,
// a STOP reported and a move done, then English → Chinese: every text of every widget a user
// can reach must follow — no English sentence left behind (capability reasons, status lines,
// messages shown earlier). The walk is generic (tests/gui/widgetwalk.h).
#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/drivetypes.h"
#include "tests/gui/widgetwalk.h"
#include "ui/bus/bustreewidget.h"
#include "ui/bus/connectioncontroller.h"
#include "ui/bus/drivedirectory.h"
#include "ui/panels/trend/trendplot.h"
#include "ui/shell/languagemanager.h"
#include "ui/shell/mainwindow.h"
#include "ui/shell/stopaction.h"
#include "ui/shell/stopreporter.h"
#include "ui/workspace/drivepanel.h"
#include "ui/workspace/driveworkspace.h"

#include <QApplication>
#include <QLoggingCategory>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

using namespace dd;

class TestLanguageWalk : public QObject
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

    // Texts that still read as English: three or more English words in a row.
    static QStringList english(MainWindow &w)
    {
        static const QRegularExpression words(QStringLiteral("[A-Za-z]{2,}(?:[ ,']+[A-Za-z]{2,}){2,}"));
        QStringList out;
        for (const widgetwalk::Text &t : widgetwalk::texts(&w)) {
            const QRegularExpressionMatch m = words.match(t.text);
            if (m.hasMatch())
                out << QStringLiteral("%1 %2 (%3): %4")
                           .arg(QString::fromLatin1(t.widget->metaObject()->className()), t.widget->objectName(),
                                t.what, t.text.left(160));
        }
        out.removeDuplicates();
        return out;
    }

    // Channel units (from the drive layer, untranslated: channelUnits()) spelled as English
    // words ("pulse", "pulse/s") in any widget's text, the trend plots' legends or axis titles
    // (painted, not widgets). Symbols (r/min, %, A, V, °C) read the same in both languages.
    static QStringList englishUnits(MainWindow &w)
    {
        static const QRegularExpression word(QStringLiteral("[a-z]{4,}"));
        QStringList patterns;
        for (const QString &u : channelUnits())
            if (word.match(u).hasMatch())
                patterns << QRegularExpression::escape(u);
        if (patterns.isEmpty())
            return {QStringLiteral("no channel unit is an English word")};
        const QRegularExpression unit(QStringLiteral("(?<![A-Za-z/])(?:%1)(?![A-Za-z/])").arg(patterns.join(u'|')));
        QList<widgetwalk::Text> texts = widgetwalk::texts(&w);
        for (TrendPlot *plot : w.findChildren<TrendPlot *>()) {
            for (const TrendPlot::Series &series : plot->series())
                texts.append({plot, QStringLiteral("legend"), series.label});
            for (int a : {int(TrendPlot::Left), int(TrendPlot::Right)})
                texts.append({plot, QStringLiteral("axis title"), plot->valueAxis(a).title});
        }
        QStringList out;
        for (const widgetwalk::Text &t : std::as_const(texts))
            if (unit.match(t.text).hasMatch())
                out << QStringLiteral("%1 %2 (%3): %4")
                           .arg(QString::fromLatin1(t.widget->metaObject()->className()), t.widget->objectName(),
                                t.what, t.text.left(160));
        out.removeDuplicates();
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
        QCoreApplication::setApplicationName(QStringLiteral("tst_languagewalk"));
        QSettings().setValue(QStringLiteral("language"), QStringLiteral("en"));
    }

    void everyTextFollowsASwitchToChinese()
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

        // Visit every tab of every drive, in English.
        for (int id : dir->connections()) {
            w.busTree()->selectDrive(id, 1);
            QTabWidget *tabs = w.workspace()->tabsFor(id, 1);
            QVERIFY(tabs);
            for (int i = 0; i < tabs->count(); ++i) {
                tabs->setCurrentIndex(i);
                QTest::qWait(50); // let each tab start what it does when shown (reads, polls)
            }
        }
        // Leave each drive on its Motion tab, a STOP reported.
        w.workspace()->setPreferredPanel(QStringLiteral("motion"));
        QSignalSpy stopped(w.stopReporter(), &StopReporter::finished);
        w.stopAction()->trigger();
        QVERIFY(stopped.wait(5000));
        QVERIFY(!english(w).isEmpty()); // the walk does see English texts
        // Every unit a drive offers is one the UI can translate.
        for (int id : dir->connections())
            for (int a : dir->drives(id))
                for (const ChannelInfo &c : dir->info(id, a).channels)
                    QVERIFY2(c.unit.isEmpty() || channelUnits().contains(c.unit), qPrintable(c.id + u' ' + c.unit));
        QTRY_VERIFY_WITH_TIMEOUT(!englishUnits(w).isEmpty(), 5000); // readouts, legends show units

        QVERIFY(w.languageManager()->apply(LanguageManager::Language::Chinese));
        QCoreApplication::sendPostedEvents();
        // Descriptions fetched again in the new language arrive from the I/O thread.
        QStringList left;
        waitFor(
            [&] {
                left = english(w);
                return left.isEmpty();
            },
            5000);
        for (const QString &l : std::as_const(left))
            qWarning("left in English: %s", qPrintable(l));
        QVERIFY2(left.isEmpty(), qPrintable(left.join(QLatin1Char('\n'))));
        QStringList units;
        waitFor(
            [&] {
                units = englishUnits(w);
                return units.isEmpty();
            },
            5000);
        for (const QString &l : std::as_const(units))
            qWarning("unit left in English: %s", qPrintable(l));
        QVERIFY2(units.isEmpty(), qPrintable(units.join(QLatin1Char('\n'))));
        QVERIFY(w.languageManager()->apply(LanguageManager::Language::English));
        QCoreApplication::sendPostedEvents();
        w.connections()->disconnectAll();
    }
};

QTEST_MAIN(TestLanguageWalk)
#include "tst_languagewalk.moc"
