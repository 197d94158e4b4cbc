// The Trend tab against a simulated drive: the recording goes on whatever tab or drive is
// shown, gaps are marked, the tab fits 1223 and 1280 px windows, the trend follows a live
// language switch.
#include <QtTest>

#include "core/trend/trendrecorder.h"
#include "tests/gui/panelrig.h"
#include "ui/panels/motion/motionpanel.h"
#include "ui/panels/trend/trendchannelpanel.h"
#include "ui/panels/trend/trendcontrols.h"
#include "ui/panels/trend/trendpanel.h"
#include "ui/panels/trend/trendplot.h"
#include "ui/panels/trend/trendview.h"
#include "ui/shell/languagemanager.h"

#include <QAbstractScrollArea>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollBar>
#include <QTemporaryDir>
#include <cmath>

using namespace dd;

namespace {

qsizetype samples(const TrendPanel *p, const QString &id = QStringLiteral("speed"))
{
    const SampleBuffer *b = p->recorder()->buffer(id);
    return b ? b->size() - b->gapCount() : 0;
}

qsizetype gaps(const TrendPanel *p, const QString &id = QStringLiteral("speed"))
{
    const SampleBuffer *b = p->recorder()->buffer(id);
    return b ? b->gapCount() : 0;
}

} // namespace

class TestTrendPanel : public QObject
{
    Q_OBJECT
private slots:
    // Issue 10 #1: jog on the Motion tab, come back: the trend recorded all along.
    void recordsWhateverTabOrDriveIsShown()
    {
        PanelRig rig;
        QString why;
        QVERIFY2(rig.start(SimBenchOptions{}, &why), qPrintable(why));
        TrendPanel *trend = rig.show<TrendPanel>(&why);
        QVERIFY2(trend, qPrintable(why));
        QVERIFY(waitUntil([&] { return trend->isRecording() && samples(trend) >= 3; }, 10000));
        // Another tab.
        rig.workspace->tabsFor(rig.id, 1)->setCurrentWidget(rig.show<MotionPanel>(&why));
        QVERIFY(!trend->isActive());
        qsizetype before = samples(trend);
        QVERIFY2(waitUntil([&] { return samples(trend) >= before + 5; }, 10000),
                 qPrintable(QStringLiteral("%1 -> %2").arg(before).arg(samples(trend))));
        // No drive shown at all.
        rig.workspace->showDrive(0, 0);
        before = samples(trend);
        QVERIFY(waitUntil([&] { return samples(trend) >= before + 5; }, 10000));
        QCOMPARE(gaps(trend), 0);
        // Stopped by the user: sampling ends with a gap mark.
        trend->view()->controls()->recordButton()->click();
        QVERIFY(!trend->isRecording());
        QCOMPARE(gaps(trend), 1);
        // Shown again: it does not start on its own any more.
        rig.workspace->showDrive(rig.id, 1);
        rig.workspace->setPreferredPanel(QStringLiteral("trend"));
        QVERIFY(trend->isActive());
        QVERIFY(!trend->isRecording());
    }

    // Issue 10 #1: a drive that falls silent leaves a gap, drawn and exported as a gap.
    void aSilentDriveLeavesAGap()
    {
        PanelRig rig;
        QString why;
        QVERIFY2(rig.start(SimBenchOptions{}, &why), qPrintable(why));
        TrendPanel *trend = rig.show<TrendPanel>(&why);
        QVERIFY2(trend, qPrintable(why));
        QVERIFY(waitUntil([&] { return samples(trend) >= 3; }, 10000));
        rig.sim.call([&] { rig.sim.bench()->setSilent(true); });
        QVERIFY(waitUntil([&] { return gaps(trend) == 1; }, 15000));
        rig.sim.call([&] { rig.sim.bench()->setSilent(false); });
        const qsizetype before = samples(trend);
        QVERIFY(waitUntil([&] { return samples(trend) >= before + 3; }, 15000));
        QCOMPARE(gaps(trend), 1); // one mark per outage
        trend->view()->refreshNow();
        const TrendPlot::Series *s = trend->view()->plot()->seriesById(QStringLiteral("speed"));
        QVERIFY(s);
        QVERIFY(std::any_of(s->points.cbegin(), s->points.cend(), [](const QPointF &p) { return std::isnan(p.y()); }));
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("t.csv"));
        QVERIFY(!trend->view()->exportCsv(csv, TrendView::ExportRange::WholeRecording));
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.readAll().contains(",nan"));
    }

    // The default rate is what the link carries (the simulator's servo-modbus at 115200
    // baud: one 9-register read takes ~5.4 ms, ~184 readings/s), not 10 Hz.
    void defaultRateUsesTheLink()
    {
        QCOMPARE(TrendPanel::rateForReadUs(5436.0), 180.0);
        QCOMPARE(TrendPanel::rateForReadUs(36900.0), 27.0);
        QCOMPARE(TrendPanel::rateForReadUs(1080.0), 920.0);
        QCOMPARE(TrendPanel::rateForReadUs(500.0), 1000.0);
        QCOMPARE(TrendPanel::rateForReadUs(0.0), TrendPanel::FallbackRateHz);
        PanelRig rig;
        QString why;
        QVERIFY2(rig.start(SimBenchOptions{}, &why), qPrintable(why));
        TrendPanel *trend = rig.show<TrendPanel>(&why);
        QVERIFY2(trend, qPrintable(why));
        QVERIFY(waitUntil([&] { return trend->defaultRateHz() != TrendPanel::FallbackRateHz; }, 10000));
        QVERIFY2(trend->defaultRateHz() >= 20.0, qPrintable(QString::number(trend->defaultRateHz())));
        QCOMPARE(trend->view()->sampleRate(), trend->defaultRateHz());
    }

    // Issue 10 #6: shuoke's long channel name; the tab fits 1223 and 1280 px windows.
    void noOverflowWithShuokesLongName_data()
    {
        QTest::addColumn<int>("windowWidth");
        QTest::addColumn<bool>("chinese");
        QTest::newRow("1223 en") << 1223 << false;
        QTest::newRow("1280 en") << 1280 << false;
        QTest::newRow("1223 zh") << 1223 << true;
        QTest::newRow("1280 zh") << 1280 << true;
    }
    void noOverflowWithShuokesLongName()
    {
        QFETCH(int, windowWidth);
        QFETCH(bool, chinese);
        PanelRig rig;
        QString why;
        SimBenchOptions o;
        o.family = Family::Shuoke;
        QVERIFY2(rig.start(o, &why), qPrintable(why));
        LanguageManager language;
        if (chinese) {
            QVERIFY(language.apply(LanguageManager::Language::Chinese));
            QCoreApplication::sendPostedEvents();
        }
        TrendPanel *trend = rig.show<TrendPanel>(&why);
        QVERIFY2(trend, qPrintable(why));
        QVERIFY(trend->recorder()->hasChannel(QStringLiteral("status")));
        trend->view()->setChannelVisible(QStringLiteral("status"), true);
        // The workspace beside the bus tree (up to ~380 px) of a window that wide.
        const int width = windowWidth - 380;
        // (The other tabs' own minimum widths are theirs to keep: this lays out the Trend tab.)
        rig.workspace->resize(width, 600);
        QCoreApplication::processEvents();
        trend->resize(width - 8, 560);
        QVERIFY2(trend->minimumSizeHint().width() <= trend->width(),
                 qPrintable(
                     QStringLiteral("needs %1 px, has %2").arg(trend->minimumSizeHint().width()).arg(trend->width())));
        for (QScrollBar *bar : trend->findChildren<QScrollBar *>())
            if (bar->orientation() == Qt::Horizontal)
                QVERIFY(!bar->isVisible());
        // Every visible widget lies inside the tab, none narrower than it needs.
        for (QWidget *w : trend->findChildren<QWidget *>()) {
            if (!w->isVisibleTo(trend) || w->inherits("QScrollBar")
                || w->parentWidget()->inherits("QAbstractScrollArea"))
                continue;
            const QRect r(w->mapTo(trend, QPoint(0, 0)), w->size());
            QVERIFY2(r.right() < trend->width() + 1,
                     qPrintable(w->metaObject()->className() + QStringLiteral(" ") + w->objectName()));
            if (w->inherits("QAbstractButton"))
                QVERIFY2(w->width() >= w->minimumSizeHint().width(), qPrintable(w->objectName()));
        }
        QVERIFY(trend->view()->plot()->legendTexts().join(QString()).contains(
            trend->recorder()->channel(QStringLiteral("status")).name));
        if (chinese)
            language.apply(LanguageManager::Language::English);
    }

    // Issue 10 #5: channel names, legend and axis titles follow a live language switch.
    void followsALiveLanguageSwitch()
    {
        PanelRig rig;
        QString why;
        QVERIFY2(rig.start(SimBenchOptions{}, &why), qPrintable(why));
        TrendPanel *trend = rig.show<TrendPanel>(&why);
        QVERIFY2(trend, qPrintable(why));
        const QString english = trend->recorder()->channel(QStringLiteral("speed")).name;
        LanguageManager language;
        QVERIFY(language.apply(LanguageManager::Language::Chinese));
        QCoreApplication::sendPostedEvents();
        QVERIFY(waitUntil([&] { return trend->recorder()->channel(QStringLiteral("speed")).name != english; }, 5000));
        trend->view()->refreshNow();
        TrendPlot *plot = trend->view()->plot();
        QCOMPARE(plot->timeTitle(), QStringLiteral("时间 [s]"));
        const QString zhName = trend->recorder()->channel(QStringLiteral("speed")).name;
        QVERIFY(plot->legendTexts().join(QString()).contains(zhName));
        QVERIFY(plot->valueAxis(TrendPlot::Left).title.contains(zhName));
        QVERIFY(trend->view()->channelPanel()->item(QStringLiteral("speed"))->text().contains(zhName));
        QCOMPARE(trend->view()->controls()->recordButton()->text(), QStringLiteral("停止记录"));
        // Every text of the tab: no English source left behind.
        for (QWidget *w : trend->findChildren<QWidget *>()) {
            QString text;
            if (auto *b = qobject_cast<QAbstractButton *>(w))
                text = b->text();
            else if (auto *l = qobject_cast<QLabel *>(w))
                text = l->text();
            for (const char *english :
                 {"Record", "Pause", "Resume", "Reset zoom", "Window", "Rate", "Export", "Point at", "sample", "Axis"})
                QVERIFY2(!text.contains(QLatin1String(english)), qPrintable(text));
        }
        QVERIFY(language.apply(LanguageManager::Language::English));
        QCoreApplication::sendPostedEvents();
        QVERIFY(waitUntil([&] { return trend->recorder()->channel(QStringLiteral("speed")).name == english; }, 5000));
    }
};

QTEST_MAIN(TestTrendPanel)
#include "tst_trendpanel.moc"
