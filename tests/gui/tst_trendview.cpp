#include <QtTest>

#include "core/trend/trendrecorder.h"
#include "ui/panels/trend/trendchannelpanel.h"
#include "ui/panels/trend/trendcontrols.h"
#include "ui/panels/trend/trendview.h"

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QLineSeries>
#include <QPushButton>
#include <QTemporaryDir>
#include <QValueAxis>
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

QValueAxis *axisX(TrendView &v)
{
    return qobject_cast<QValueAxis *>(v.chart()->axes(Qt::Horizontal).value(0));
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

} // namespace

class TestTrendView : public QObject
{
    Q_OBJECT
private:
    std::unique_ptr<TrendRecorder> m_rec;
    std::unique_ptr<TrendView> m_view;

    void makeView(int samples)
    {
        m_view.reset();
        m_rec = std::make_unique<TrendRecorder>();
        m_rec->setChannels(fourChannels());
        feed(*m_rec, 0, samples);
        m_view = std::make_unique<TrendView>(m_rec.get());
        m_view->resize(1200, 700);
        m_view->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
        m_view->refreshNow();
    }

    int plotWidth() const { return static_cast<int>(m_view->chart()->plotArea().width()); }

private slots:
    void cleanup()
    {
        m_view.reset();
        m_rec.reset();
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
            QLineSeries *s = m_view->series(c.id);
            QVERIFY(s);
            QVERIFY2(s->count() <= 2 * width,
                     qPrintable(QStringLiteral("%1: %2 points for %3 px").arg(c.id).arg(s->count()).arg(width)));
            QVERIFY(s->count() > 0);
            QVERIFY(s->count() < inWindow); // actually decimated
        }
        // The window follows the newest sample.
        QCOMPARE(axisX(*m_view)->max() - axisX(*m_view)->min(), double(window));
        if (window <= 100)
            QCOMPARE(axisX(*m_view)->max(), 99.999);
    }

    void peaksSurviveDecimation()
    {
        m_rec = std::make_unique<TrendRecorder>();
        m_rec->setChannels(fourChannels().mid(0, 1));
        for (int i = 0; i < 100000; ++i)
            m_rec->append(Speed, T0 + qint64(i) * 1000, i == 54321 ? 9999.0 : 100.0);
        m_view = std::make_unique<TrendView>(m_rec.get());
        m_view->resize(900, 500);
        m_view->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_view.get()));
        m_view->setWindowSeconds(600);
        m_view->refreshNow();
        const QList<QPointF> pts = m_view->series(Speed)->points();
        QVERIFY(pts.size() <= 2 * plotWidth());
        QVERIFY(pts.contains(QPointF(54.321, 9999.0)));
    }

    void pauseFreezesViewButKeepsRecording()
    {
        makeView(20000);
        QCOMPARE(axisX(*m_view)->max(), 19.999 + 10.001); // young recording: [0, 30] grows
        feed(*m_rec, 20000, 20000);
        m_view->refreshNow();
        QCOMPARE(axisX(*m_view)->max(), 39.999);

        m_view->controls()->pauseButton()->click();
        QVERIFY(m_rec->isPaused());
        QCOMPARE(m_view->controls()->pauseButton()->text(), QStringLiteral("Resume"));
        feed(*m_rec, 40000, 5000);
        m_view->refreshNow();
        QCOMPARE(m_rec->buffer(Speed)->size(), 45000); // still recording
        QCOMPARE(axisX(*m_view)->max(), 39.999);       // view frozen
        QVERIFY(m_view->series(Speed)->points().last().x() <= 40.0);

        m_view->controls()->pauseButton()->click();
        QVERIFY(!m_rec->isPaused());
        m_view->refreshNow();
        QCOMPARE(axisX(*m_view)->max(), 44.999);
    }

    void zoomPausesAndResets()
    {
        makeView(60000);
        QValueAxis *x = axisX(*m_view);
        const double span = x->max() - x->min();
        const QRectF plot = m_view->chart()->plotArea();
        m_view->chart()->zoomIn(
            QRectF(plot.left() + plot.width() * 0.25, plot.top(), plot.width() * 0.1, plot.height()));
        QVERIFY(m_view->isZoomed());
        QVERIFY(m_rec->isPaused());
        m_view->refreshNow();
        const double zoomedMin = x->min();
        const double zoomedSpan = x->max() - x->min();
        QVERIFY2(zoomedSpan < span * 0.2, qPrintable(QString::number(zoomedSpan)));
        // Re-decimated at full resolution for the zoomed range: ~3 s at 1 kHz is more
        // samples than pixels, so the series is dense but still bounded.
        const QList<QPointF> pts = m_view->series(Torque)->points();
        QVERIFY(pts.size() <= 2 * plotWidth());
        QVERIFY(pts.size() > plotWidth());
        QVERIFY(pts.at(1).x() >= zoomedMin);

        // New samples do not move a zoomed view.
        feed(*m_rec, 60000, 1000);
        m_view->refreshNow();
        QCOMPARE(x->min(), zoomedMin);

        m_view->resetZoom();
        QVERIFY(!m_view->isZoomed());
        QVERIFY(m_rec->isPaused()); // still paused: the window ending where it paused
        QCOMPARE(x->max() - x->min(), 30.0);
        QCOMPARE(x->max(), 59.999);

        m_view->chart()->zoomIn(QRectF(plot.left() + 10, plot.top() + 10, 100, 100));
        QVERIFY(m_view->isZoomed());
        m_rec->setPaused(false); // resume drops the zoom
        QVERIFY(!m_view->isZoomed());
        m_view->refreshNow();
        QCOMPARE(x->max(), 60.999);
    }

    void rubberBandDragZooms()
    {
        makeView(60000);
        QWidget *vp = m_view->chartView()->viewport();
        const QRectF plot = m_view->chart()->plotArea();
        const auto toViewport = [&](const QPointF &chartPos) {
            return m_view->chartView()->mapFromScene(m_view->chart()->mapToScene(chartPos));
        };
        const QPoint a = toViewport(plot.topLeft() + QPointF(plot.width() * 0.4, 5));
        const QPoint b = toViewport(plot.topLeft() + QPointF(plot.width() * 0.6, plot.height() - 5));
        QTest::mousePress(vp, Qt::LeftButton, Qt::NoModifier, a);
        QTest::mouseMove(vp, (a + b) / 2);
        QTest::mouseMove(vp, b);
        QTest::mouseRelease(vp, Qt::LeftButton, Qt::NoModifier, b);
        QVERIFY(m_view->isZoomed());
        QVERIFY(m_rec->isPaused());
        QTRY_VERIFY(m_view->visibleToUs() - m_view->visibleFromUs() < 8000000); // ~6 s of 30
        QVERIFY(m_view->visibleFromUs() > T0 + 36000000);
        // Right click zooms out again (still zoomed relative to the window, still paused).
        QTest::mouseClick(vp, Qt::RightButton, Qt::NoModifier, (a + b) / 2);
        QTRY_VERIFY(m_view->visibleToUs() - m_view->visibleFromUs() > 8000000);
        QVERIFY(m_rec->isPaused());
    }

    void cursorReadout()
    {
        makeView(30000);
        const QRectF plot = m_view->chart()->plotArea();
        const QPointF scene = m_view->chart()->mapToScene(plot.center());
        const QPoint pos = m_view->chartView()->mapFromScene(scene);
        QTest::mouseMove(m_view->chartView()->viewport(), pos);
        const QString text = m_view->cursorReadout();
        QVERIFY2(text.contains(QStringLiteral("t = ")), qPrintable(text));
        QVERIFY2(
            text.contains(QStringLiteral("Bus voltage: ") + QLocale().toString(311.5, 'f', 1) + QStringLiteral(" V")),
            qPrintable(text));
        QVERIFY(text.contains(QStringLiteral("Speed: ")));
        // t at the middle of the [0, 30] s window, to a pixel.
        const double t = QLocale().toDouble(text.section(QStringLiteral("t = "), 1).section(QLatin1Char(' '), 0, 0));
        QVERIFY2(std::fabs(t - 15.0) < 30.0 / plot.width() * 2, qPrintable(text));
        // Hidden channels are not read out.
        m_view->setChannelVisible(Bus, false);
        m_view->setCursorPosition(pos);
        QVERIFY(!m_view->cursorReadout().contains(QStringLiteral("Bus voltage")));
        // Outside the plot area: no cursor.
        m_view->setCursorPosition(QPoint(1, 1));
        QVERIFY(!m_view->cursorReadout().contains(QStringLiteral("t = ")));
    }

    void exportsParse()
    {
        makeView(50000);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString all = dir.filePath(QStringLiteral("all.csv"));
        QVERIFY(!m_view->exportCsv(all, TrendView::ExportRange::WholeRecording));
        QStringList lines = readLines(all);
        QCOMPARE(lines.size(), 1 + 50000);
        QCOMPARE(lines.first(), QStringLiteral("time_s,speed [r/min],torque [%],current [A],bus-voltage [V]"));
        QCOMPARE(lines.at(1).section(QLatin1Char(','), 0, 0), QStringLiteral("0.000000"));
        QCOMPARE(lines.last().section(QLatin1Char(','), 0, 0), QStringLiteral("49.999000"));
        QCOMPARE(lines.last().section(QLatin1Char(','), 4, 4), QStringLiteral("311.5"));
        for (const QString &l : lines.mid(1, 100))
            QCOMPARE(l.count(QLatin1Char(',')), 4);

        // Visible window of the checked channels only: the last 30 s.
        m_view->setChannelVisible(Torque, false);
        m_view->setChannelVisible(Current, false);
        m_view->refreshNow();
        const QString win = dir.filePath(QStringLiteral("window.csv"));
        QVERIFY(!m_view->exportCsv(win, TrendView::ExportRange::VisibleWindow));
        lines = readLines(win);
        QCOMPARE(lines.first(), QStringLiteral("time_s,speed [r/min],bus-voltage [V]"));
        QCOMPARE(lines.size(), 1 + 30001); // 19.999 .. 49.999 s inclusive
        QCOMPARE(lines.at(1).section(QLatin1Char(','), 0, 0), QStringLiteral("19.999000"));

        const QString png = dir.filePath(QStringLiteral("plot.png"));
        QVERIFY(!m_view->exportPng(png));
        QImage image(png);
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), m_view->chartView()->size() * m_view->chartView()->devicePixelRatio());

        const Error e = m_view->exportPng(dir.filePath(QStringLiteral("no/such/dir/p.png")));
        QCOMPARE(e.code, ErrorCode::FileError);
    }

    void channelVisibilityAndScale()
    {
        makeView(10000);
        QCheckBox *box = m_view->channelPanel()->checkBox(Speed);
        QVERIFY(box);
        QVERIFY(box->isChecked());
        box->click();
        QVERIFY(!m_view->isChannelVisible(Speed));
        QVERIFY(!m_view->series(Speed)->isVisible());
        QCOMPARE(m_view->series(Speed)->count(), 0);
        box->click();
        QVERIFY(m_view->series(Speed)->count() > 0);

        // Scale and offset apply to the plot only.
        m_view->setChannelScale(Bus, 0.5, 10.0);
        const QList<QPointF> pts = m_view->series(Bus)->points();
        QVERIFY(!pts.isEmpty());
        for (const QPointF &p : pts)
            QCOMPARE(p.y(), 311.5 * 0.5 + 10.0);
        QVERIFY(m_view->series(Bus)->name().contains(QStringLiteral("×")));
        QVERIFY(m_view->cursorReadout().isEmpty() == false);
    }

    void sampleRateControlOnlySignals()
    {
        makeView(10);
        QSignalSpy spy(m_view.get(), &TrendView::sampleRateChanged);
        m_view->setSampleRate(50.0);
        QCOMPARE(spy.count(), 0);
        QCOMPARE(m_view->sampleRate(), 50.0);
        auto *spin = m_view->controls()->findChild<QDoubleSpinBox *>();
        QVERIFY(spin);
        spin->setValue(200.0);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(spy.first().at(0).toDouble(), 200.0);
        QCOMPARE(m_rec->buffer(Speed)->size(), 10); // the view never feeds the recorder
    }

    void followsChannelChanges()
    {
        makeView(1000);
        m_rec->addChannel(
            {QStringLiteral("position-error"), QStringLiteral("Position error"), QStringLiteral("pulse"), 0});
        QVERIFY(m_view->series(QStringLiteral("position-error")));
        QCOMPARE(m_view->chart()->series().size(), 5);
        m_rec->setChannels(fourChannels().mid(0, 2));
        QCOMPARE(m_view->chart()->series().size(), 2);
        QVERIFY(!m_view->series(Bus));
        m_rec->clear();
        m_view->refreshNow();
        QCOMPARE(m_view->series(Speed)->count(), 0);
    }
};

QTEST_MAIN(TestTrendView)
#include "tst_trendview.moc"
