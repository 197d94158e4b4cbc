#include <QtTest>

#include "core/trend/trendrecorder.h"
#include "ui/panels/trend/trendchannelpanel.h"
#include "ui/panels/trend/trendcontrols.h"
#include "ui/panels/trend/trendplot.h"
#include "ui/panels/trend/trendview.h"

#include <QDoubleSpinBox>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QTemporaryDir>
#include <QToolButton>
#include <cmath>

using namespace dd;

namespace {

const QString Speed = QStringLiteral("speed");
const QString Torque = QStringLiteral("torque");
const QString Current = QStringLiteral("current");
const QString Bus = QStringLiteral("bus-voltage");

QList<TrendChannel> fourChannels()
{
    return {{Speed, QStringLiteral("Speed"), QStringLiteral("r/min"), 0},
            {Torque, QStringLiteral("Torque"), QStringLiteral("%"), 1},
            {Current, QStringLiteral("Current"), QStringLiteral("A"), 2},
            {Bus, QStringLiteral("Bus voltage"), QStringLiteral("V"), 1}};
}

constexpr qint64 T0 = 5000000000; // arbitrary clock origin (µs)

// n readings at 1 kHz of all four channels, starting at `first`.
void feed(TrendRecorder &rec, int first, int n)
{
    for (int i = first; i < first + n; ++i) {
        const qint64 t = T0 + qint64(i) * 1000;
        rec.append(Speed, t, 1500.0 * std::sin(i * 0.001));
        rec.append(Torque, t, 20.0 * std::sin(i * 0.013) + (i % 7));
        rec.append(Current, t, 3.0 * std::cos(i * 0.002));
        rec.append(Bus, t, 311.5);
    }
}

QStringList readLines(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    QStringList lines = QString::fromUtf8(f.readAll()).split(QLatin1Char('\n'));
    if (!lines.isEmpty() && lines.last().isEmpty())
        lines.removeLast();
    return lines;
}

int breaks(const QList<QPointF> &points)
{
    return int(std::count_if(points.cbegin(), points.cend(), [](const QPointF &p) { return std::isnan(p.y()); }));
}

} // namespace

class TestTrendView : public QObject
{
    Q_OBJECT
private:
    std::unique_ptr<TrendRecorder> m_rec;
    std::unique_ptr<TrendView> m_view;

    void makeView(int samples, QList<TrendChannel> channels = fourChannels())
    {
        m_view.reset();
        m_rec = std::make_unique<TrendRecorder>();
        m_rec->setChannels(channels);
        feed(*m_rec, 0, samples);
        m_view = std::make_unique<TrendView>(m_rec.get());
        m_view->resize(1000, 600);
        m_view->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
        m_view->refreshNow();
    }

    TrendPlot *plot() const { return m_view->plot(); }
    QList<QPointF> points(const QString &id) const
    {
        const TrendPlot::Series *s = plot()->seriesById(id);
        return s ? s->points : QList<QPointF>();
    }
    int plotWidth() const { return static_cast<int>(plot()->plotRect().width()); }

private slots:
    void cleanup()
    {
        m_view.reset();
        m_rec.reset();
    }

    void theLayoutGivesThePlotMostOfTheTab()
    {
        makeView(1000);
        const QRect plotBox = plot()->geometry();
        QVERIFY2(plotBox.width() * plotBox.height() > 0.5 * m_view->width() * m_view->height(),
                 qPrintable(QStringLiteral("%1x%2").arg(plotBox.width()).arg(plotBox.height())));
        // The channel list is compact: no spin boxes per row.
        QVERIFY(m_view->findChildren<QDoubleSpinBox *>().size() == 1); // the sample rate only
        QVERIFY(m_view->channelPanel()->width() <= 220);
    }

    void seriesStayWithinTwoPointsPerPixel_data()
    {
        QTest::addColumn<int>("window");
        QTest::newRow("10 s") << 10;
        QTest::newRow("1 min") << 60;
        QTest::newRow("10 min") << 600;
    }
    void seriesStayWithinTwoPointsPerPixel()
    {
        QFETCH(int, window);
        makeView(100000); // 100 s at 1 kHz, 4 channels: 400k samples
        m_view->setWindowSeconds(window);
        m_view->refreshNow();
        const int width = plotWidth();
        QVERIFY2(width > 100, qPrintable(QString::number(width)));
        const qint64 inWindow = std::min<qint64>(qint64(window) * 1000, 100000);
        for (const TrendChannel &c : fourChannels()) {
            const QList<QPointF> pts = points(c.id);
            QVERIFY2(pts.size() <= 2 * width, qPrintable(QStringLiteral("%1: %2 points").arg(c.id).arg(pts.size())));
            QVERIFY(pts.size() > 0);
            QVERIFY(pts.size() < inWindow); // actually decimated
        }
        QCOMPARE(plot()->timeMax() - plot()->timeMin(), double(window));
        if (window < 100)
            QCOMPARE(plot()->timeMax(), 99.999); // follows the newest sample
    }

    // Issue 10 #1: a gap in the recording is a gap in the plot and the CSV, not a ramp.
    void gapsAreDrawnAndExportedAsGaps()
    {
        makeView(0, {fourChannels().at(1)});
        m_rec->append(Torque, T0, 0.0);
        m_rec->append(Torque, T0 + 1000000, 0.0);
        m_rec->appendGap(T0 + 1500000); // the link was lost
        m_rec->append(Torque, T0 + 8000000, 8.0);
        m_rec->append(Torque, T0 + 9000000, 8.0);
        m_view->refreshNow();
        const QList<QPointF> pts = points(Torque);
        QCOMPARE(breaks(pts), 1);
        // No segment of the drawn line crosses the gap.
        for (int i = 1; i < pts.size(); ++i)
            if (!std::isnan(pts.at(i).y()) && !std::isnan(pts.at(i - 1).y()))
                QVERIFY2(!(pts.at(i - 1).x() < 1.5 && pts.at(i).x() > 1.5), "a ramp across the gap");
        // The readout in the gap says there is no value (not an interpolated 4 %).
        m_view->setHoverTime(4.0);
        QVERIFY2(m_view->cursorReadout().contains(QStringLiteral("Torque: –")), qPrintable(m_view->cursorReadout()));
        QTemporaryDir dir;
        const QString csv = dir.filePath(QStringLiteral("gap.csv"));
        QVERIFY(!m_view->exportCsv(csv, TrendView::ExportRange::WholeRecording));
        QCOMPARE(readLines(csv),
                 (QStringList{QStringLiteral("time_s,torque [%]"), QStringLiteral("0.000000,0"),
                              QStringLiteral("1.000000,0"), QStringLiteral("1.500000,nan"),
                              QStringLiteral("8.000000,8"), QStringLiteral("9.000000,8")}));
    }

    // Issue 10 #1: the readout shows the value at the cursor (the line), not the next sample.
    void hoverReadsTheLine()
    {
        makeView(0, {fourChannels().at(1)});
        m_rec->append(Torque, T0, 0.0);
        m_rec->append(Torque, T0 + 2000000, 8.0);
        m_view->refreshNow();
        m_view->setHoverTime(0.5);
        QVERIFY2(m_view->cursorReadout().contains(QStringLiteral("Torque: 2.0 %")),
                 qPrintable(m_view->cursorReadout()));
        // The mouse does the same.
        const QRectF r = plot()->plotRect();
        QTest::mouseMove(plot(), QPoint(int(plot()->xAtTime(1.0)), int(r.center().y())));
        QTRY_VERIFY2(!m_view->cursorReadout().contains(QStringLiteral("t = 0.500")),
                     qPrintable(m_view->cursorReadout()));
        const QRegularExpressionMatch m = QRegularExpression(QStringLiteral("t = ([0-9.]+) s   Torque: ([0-9.]+) %"))
                                              .match(m_view->cursorReadout());
        QVERIFY2(m.hasMatch(), qPrintable(m_view->cursorReadout()));
        const double t = m.captured(1).toDouble();
        QVERIFY(std::fabs(t - 1.0) < 0.05);
        QCOMPARE(m.captured(2), QString::number(4.0 * t, 'f', 1)); // on the line from 0 to 8 over 2 s
    }

    void twoCursorsGiveDeltas()
    {
        makeView(0, {fourChannels().at(0), fourChannels().at(1)});
        m_rec->append(Speed, T0, 100.0);
        m_rec->append(Torque, T0, 1.0);
        m_rec->append(Speed, T0 + 4000000, 500.0);
        m_rec->append(Torque, T0 + 4000000, 9.0);
        m_view->refreshNow();
        m_view->setMarker(0, 1.0);
        m_view->setMarker(1, 3.0);
        const QString text = m_view->markerReadout();
        QVERIFY2(text.contains(QStringLiteral("Δt = 2.000 s")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("Δ Speed: 200 r/min")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("Δ Torque: 4.0 %")), qPrintable(text));
        QCOMPARE(plot()->marker(1), std::optional<double>(3.0));
        // Click places A, Shift+click B; Del removes both. Esc is STOP in the whole
        // application: the plot leaves it to the window's shortcut.
        const int y = int(plot()->plotRect().center().y());
        QTest::mouseClick(plot(), Qt::LeftButton, {}, QPoint(int(plot()->xAtTime(2.0)), y));
        QVERIFY(std::fabs(*m_view->marker(0) - 2.0) < 0.05);
        QTest::mouseClick(plot(), Qt::LeftButton, Qt::ShiftModifier, QPoint(int(plot()->xAtTime(2.5)), y));
        QVERIFY(std::fabs(*m_view->marker(1) - 2.5) < 0.05);
        plot()->setFocus();
        QKeyEvent esc(QEvent::KeyPress, Qt::Key_Escape, Qt::NoModifier);
        QApplication::sendEvent(plot(), &esc);
        QVERIFY(!esc.isAccepted());
        QVERIFY(m_view->marker(0) && m_view->marker(1));
        QTest::keyClick(plot(), Qt::Key_Delete);
        QVERIFY(!m_view->marker(0) && !m_view->marker(1));
    }

    // Different units: their own axes, left and right, assignable; readable ticks.
    void channelsWithDifferentUnitsGetTheirOwnAxes()
    {
        makeView(20000);
        QCOMPARE(m_view->channelAxis(Speed), int(TrendPlot::Left));
        QCOMPARE(m_view->channelAxis(Torque), int(TrendPlot::Right));
        QVERIFY(plot()->valueAxis(TrendPlot::Left).used);
        QVERIFY(plot()->valueAxis(TrendPlot::Right).used);
        QCOMPARE(plot()->valueAxis(TrendPlot::Left).title, QStringLiteral("Speed [r/min]"));
        // Each axis fits its own data: speed spans thousands, torque tens.
        QVERIFY(plot()->valueAxis(TrendPlot::Left).max >= 1400);
        QVERIFY(plot()->valueAxis(TrendPlot::Right).max < 400);
        // Ticks on round steps, labelled without noise digits.
        for (int axis : {-1, 0, 1}) {
            const QList<double> ticks = plot()->ticks(axis);
            QVERIFY(ticks.size() >= 2);
            const double step = ticks.at(1) - ticks.at(0);
            const double mantissa = step / std::pow(10.0, std::floor(std::log10(step)));
            QVERIFY2(std::fabs(mantissa - 1) < 1e-6 || std::fabs(mantissa - 2) < 1e-6 || std::fabs(mantissa - 5) < 1e-6,
                     qPrintable(QString::number(step)));
            for (double t : ticks)
                QVERIFY2(TrendPlot::tickLabel(t, step).size() <= 7, qPrintable(TrendPlot::tickLabel(t, step)));
        }
        QCOMPARE(TrendPlot::tickLabel(194.45700001, 50), QStringLiteral("194"));
        QCOMPARE(TrendPlot::tickLabel(0.30000000000000004, 0.1), QStringLiteral("0.3"));
        // Assignable, from the channel's menu.
        QMenu *menu = m_view->channelPanel()->menuFor(Torque);
        menu->findChild<QAction *>(QStringLiteral("leftAxis"))->trigger();
        QCOMPARE(m_view->channelAxis(Torque), int(TrendPlot::Left));
        m_view->setChannelVisible(Current, false);
        m_view->setChannelVisible(Bus, false);
        m_view->refreshNow();
        QVERIFY(!plot()->valueAxis(TrendPlot::Right).used);
        QCOMPARE(plot()->valueAxis(TrendPlot::Left).title, QStringLiteral("r/min, %"));
    }

    void shownChannelsHaveDistinctColours()
    {
        QList<TrendChannel> many;
        for (int i = 0; i < 14; ++i)
            many.append({QStringLiteral("c%1").arg(i), QStringLiteral("Channel %1").arg(i), QStringLiteral("V"), 0});
        makeView(0, many);
        for (const TrendChannel &c : many)
            m_view->setChannelVisible(c.id, true);
        QSet<QRgb> seen;
        for (const TrendChannel &c : many)
            seen.insert(m_view->channelColor(c.id).rgb());
        QCOMPARE(seen.size(), many.size());
    }

    // Issue 10 #6: a long channel name does not widen the view or get cut in the legend.
    void longNamesNeitherWidenNorCut()
    {
        const QString longName = QStringLiteral("Status bits (running, left limit, origin, right limit, enable)");
        makeView(0, {{QStringLiteral("status"), longName, QString(), 0}, fourChannels().at(0)});
        m_view->setChannelVisible(QStringLiteral("status"), true);
        m_view->refreshNow();
        QVERIFY2(m_view->minimumSizeHint().width() <= 700,
                 qPrintable(QString::number(m_view->minimumSizeHint().width())));
        QVERIFY(m_view->channelPanel()->item(QStringLiteral("status"))->toolTip().contains(longName));
        QVERIFY(plot()->legendTexts().first().startsWith(longName)); // wrapped, not cut
    }

    void zoomAndPanByMouseAndKeyboard()
    {
        makeView(60000);
        QCOMPARE(plot()->timeMax(), 59.999);
        plot()->setFocus();
        QTest::keyClick(plot(), Qt::Key_Plus);
        QVERIFY(m_view->isZoomed());
        QVERIFY(m_rec->isPaused());
        QVERIFY(plot()->timeMax() - plot()->timeMin() < 30.0 * 0.85);
        const double before = plot()->timeMin();
        QTest::keyClick(plot(), Qt::Key_Left);
        QVERIFY(plot()->timeMin() < before);
        QTest::keyClick(plot(), Qt::Key_Home);
        QVERIFY(!m_view->isZoomed());
        QCOMPARE(plot()->timeMax() - plot()->timeMin(), 30.0);
        // Drag a rectangle: time and values zoom.
        const QRectF r = plot()->plotRect();
        const QPoint a(int(r.left() + r.width() * 0.5), int(r.top() + 10));
        const QPoint b(int(r.left() + r.width() * 0.7), int(r.bottom() - 10));
        QTest::mousePress(plot(), Qt::LeftButton, {}, a);
        QTest::mouseMove(plot(), (a + b) / 2);
        QTest::mouseMove(plot(), b);
        QTest::mouseRelease(plot(), Qt::LeftButton, {}, b);
        QVERIFY(m_view->isZoomed());
        QVERIFY(plot()->timeMax() - plot()->timeMin() < 30.0 * 0.25);
        QVERIFY(m_view->visibleFromUs() > T0 + 40000000);
        // The wheel zooms out around the pointer; reset shows the window again.
        QWheelEvent wheel(QPointF(r.center()), plot()->mapToGlobal(r.center()), {}, QPoint(0, -120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        const double span = plot()->timeMax() - plot()->timeMin();
        QApplication::sendEvent(plot(), &wheel);
        QVERIFY(plot()->timeMax() - plot()->timeMin() > span);
        m_view->controls()->findChild<QPushButton *>()->setFocus();
        m_view->resetZoom();
        QVERIFY(!m_view->isZoomed());
    }

    void pauseFreezesViewButKeepsRecording()
    {
        makeView(20000);
        QCOMPARE(plot()->timeMax(), 30.0 - 0.0); // young recording: [0, 30] grows
        feed(*m_rec, 20000, 20000);
        m_view->refreshNow();
        QCOMPARE(plot()->timeMax(), 39.999);
        m_view->controls()->pauseButton()->click();
        QVERIFY(m_rec->isPaused());
        feed(*m_rec, 40000, 5000);
        m_view->refreshNow();
        QCOMPARE(m_rec->buffer(Speed)->size(), 45000); // still recording
        QCOMPARE(plot()->timeMax(), 39.999);           // view frozen
        m_view->controls()->pauseButton()->click();
        m_view->refreshNow();
        QCOMPARE(plot()->timeMax(), 44.999);
    }

    void exportsWriteAndSayWhere()
    {
        makeView(50000);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString all = dir.filePath(QStringLiteral("all.csv"));
        QVERIFY(m_view->exportFile(TrendView::ExportKind::CsvWhole, all));
        QVERIFY2(m_view->message().contains(QDir::toNativeSeparators(all)), qPrintable(m_view->message()));
        QStringList lines = readLines(all);
        QCOMPARE(lines.size(), 1 + 50000);
        QCOMPARE(lines.first(), QStringLiteral("time_s,speed [r/min],torque [%],current [A],bus-voltage [V]"));
        QCOMPARE(lines.last().section(QLatin1Char(','), 0, 0), QStringLiteral("49.999000"));

        m_view->setChannelVisible(Torque, false);
        m_view->setChannelVisible(Current, false);
        m_view->refreshNow();
        const QString win = dir.filePath(QStringLiteral("window.csv"));
        QVERIFY(!m_view->exportCsv(win, TrendView::ExportRange::VisibleWindow));
        lines = readLines(win);
        QCOMPARE(lines.first(), QStringLiteral("time_s,speed [r/min],bus-voltage [V]"));
        QCOMPARE(lines.size(), 1 + 30001); // 19.999 .. 49.999 s inclusive

        m_view->setDriveTitle(QStringLiteral("Servo (Modbus), address 1"));
        const QStringList block = m_view->titleBlock();
        QVERIFY(block.join(QLatin1Char('\n')).contains(QStringLiteral("Servo (Modbus), address 1")));
        QVERIFY(block.join(QLatin1Char('\n')).contains(QStringLiteral("Speed [r/min]")));
        QVERIFY(block.join(QLatin1Char('\n')).contains(QStringLiteral("Bus voltage [V]")));
        const QString png = dir.filePath(QStringLiteral("plot.png"));
        QVERIFY(m_view->exportFile(TrendView::ExportKind::Png, png));
        const QImage image(png);
        QCOMPARE(image.width(), plot()->width());
        QVERIFY(image.height() > plot()->height()); // the title block on top
        const QString svg = dir.filePath(QStringLiteral("plot.svg"));
        QVERIFY(m_view->exportFile(TrendView::ExportKind::Svg, svg));
        QFile svgFile(svg);
        QVERIFY(svgFile.open(QIODevice::ReadOnly));
        const QByteArray svgText = svgFile.readAll();
        QVERIFY(svgText.startsWith("<?xml") || svgText.contains("<svg"));
        QVERIFY(svgText.contains("Servo (Modbus), address 1"));

        QVERIFY(!m_view->exportFile(TrendView::ExportKind::Png, dir.filePath(QStringLiteral("no/such/dir/x.png"))));
        QVERIFY(m_view->message().contains(QStringLiteral("Cannot save")));
    }

    void channelListAndMenu()
    {
        makeView(10);
        QListWidgetItem *item = m_view->channelPanel()->item(Speed);
        QVERIFY(item);
        QCOMPARE(item->checkState(), Qt::Checked);
        item->setCheckState(Qt::Unchecked);
        QVERIFY(!m_view->isChannelVisible(Speed));
        QVERIFY(!plot()->seriesById(Speed));
        item->setCheckState(Qt::Checked);
        QVERIFY(plot()->seriesById(Speed));
        m_view->setChannelScale(Bus, 0.5, 10.0);
        for (const QPointF &p : points(Bus))
            QCOMPARE(p.y(), 311.5 * 0.5 + 10.0);
        QVERIFY(plot()->seriesById(Bus)->label.contains(QStringLiteral("×")));
        QMenu *menu = m_view->channelPanel()->menuFor(Bus);
        QAction *reset = menu->findChild<QAction *>(QStringLiteral("resetScale"));
        QVERIFY(reset && reset->isEnabled());
        reset->trigger();
        QCOMPARE(points(Bus).first().y(), 311.5);
    }

    void sampleRateAndRecordOnlySignal()
    {
        makeView(10);
        QSignalSpy rate(m_view.get(), &TrendView::sampleRateChanged);
        QSignalSpy record(m_view.get(), &TrendView::recordToggled);
        m_view->setSampleRate(50.0);
        m_view->setRecording(true);
        QCOMPARE(rate.count(), 0);
        QCOMPARE(record.count(), 0);
        QCOMPARE(m_view->controls()->recordButton()->text(), QStringLiteral("Stop recording"));
        m_view->controls()->recordButton()->click();
        QCOMPARE(record.count(), 1);
        QCOMPARE(record.first().at(0).toBool(), false);
        QCOMPARE(m_rec->buffer(Speed)->size(), 10); // the view never feeds the recorder
    }

    void followsChannelChanges()
    {
        makeView(100);
        QList<TrendChannel> chans = fourChannels();
        chans.append({QStringLiteral("position-error"), QStringLiteral("Following error"), QStringLiteral("pulse"), 0});
        m_rec->setChannels(chans);
        QVERIFY(m_view->channelPanel()->item(QStringLiteral("position-error")));
        QCOMPARE(m_view->channelPanel()->list()->count(), 5);
        m_rec->setChannels({chans.at(0), chans.at(4)});
        QCOMPARE(m_view->channelPanel()->list()->count(), 2);
        QVERIFY(!plot()->seriesById(Bus));
    }
};

QTEST_MAIN(TestTrendView)
#include "tst_trendview.moc"
