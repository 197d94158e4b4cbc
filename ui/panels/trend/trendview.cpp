#include "ui/panels/trend/trendview.h"

#include "core/trend/csvwriter.h"
#include "core/trend/trendaxisscale.h"
#include "core/trend/trendplotbuilder.h"
#include "core/trend/trendrecorder.h"
#include "ui/panels/trend/trendchannelpanel.h"
#include "ui/panels/trend/trendcontrols.h"

#include <QChart>
#include <QChartView>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QGraphicsLineItem>
#include <QHBoxLayout>
#include <QLabel>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLocale>
#include <QMessageBox>
#include <QMouseEvent>
#include <QSaveFile>
#include <QScrollArea>
#include <QStyle>
#include <QVBoxLayout>
#include <QValueAxis>
#include <cmath>

namespace dd {

namespace {

constexpr int RefreshIntervalMs = 40;         // 25 Hz
constexpr int SlowestRefreshIntervalMs = 200; // 5 Hz on a machine too slow for 25

// Distinguishable on white and in grey-scale print; repeats after eight channels.
const QList<QColor> &seriesColors()
{
    static const QList<QColor> colors{QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28), QColor(0x2c, 0xa0, 0x2c),
                                      QColor(0xff, 0x7f, 0x0e), QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                                      QColor(0x17, 0xbe, 0xcf), QColor(0x7f, 0x7f, 0x7f)};
    return colors;
}

qint64 secondsToUs(double s)
{
    return static_cast<qint64>(std::llround(s * 1e6));
}

} // namespace

TrendView::TrendView(TrendRecorder *recorder, QWidget *parent)
    : QWidget(parent)
    , m_recorder(recorder)
{
    buildUi();
    m_timer.setInterval(RefreshIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &TrendView::refreshNow);
    connect(m_recorder, &TrendRecorder::channelsChanged, this, &TrendView::rebuildSeries);
    connect(m_recorder, &TrendRecorder::pausedChanged, this, &TrendView::onPausedChanged);
    connect(m_recorder, &TrendRecorder::cleared, this, [this] {
        dropZoom();
        invalidate();
    });
    rebuildSeries();
    onPausedChanged(m_recorder->isPaused());
    retranslateUi();
}

TrendView::~TrendView() = default;

void TrendView::buildUi()
{
    buildChart();
    buildControls();
    buildChannelPanel();
    m_readout = new QLabel(this);
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_status = new QLabel(this);

    auto *plotRow = new QHBoxLayout;
    plotRow->addWidget(m_chartView, 1);
    plotRow->addWidget(m_panelScroll);
    auto *bottom = new QHBoxLayout;
    bottom->addWidget(m_readout, 1);
    bottom->addWidget(m_status);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_controls);
    layout->addLayout(plotRow, 1);
    layout->addLayout(bottom);
}

void TrendView::buildChart()
{
    m_chart = new QChart;
    m_chart->setAnimationOptions(QChart::NoAnimation);
    m_chart->legend()->setAlignment(Qt::AlignTop);
    m_axisX = new QValueAxis(m_chart);
    m_axisY = new QValueAxis(m_chart);
    m_axisX->setLabelFormat(QStringLiteral("%g"));
    m_axisX->setTickType(QValueAxis::TicksDynamic); // round times while the axis scrolls
    m_axisX->setTickAnchor(0.0);
    m_axisX->setTickInterval(5.0);
    m_axisY->setLabelFormat(QStringLiteral("%g"));
    m_chart->addAxis(m_axisX, Qt::AlignBottom);
    m_chart->addAxis(m_axisY, Qt::AlignLeft);
    connect(m_axisX, &QValueAxis::rangeChanged, this, &TrendView::onAxisRangeChanged);
    connect(m_axisY, &QValueAxis::rangeChanged, this, &TrendView::onAxisRangeChanged);

    m_chartView = new QChartView(m_chart, this);
    m_chartView->setRenderHint(QPainter::Antialiasing, false);
    m_chartView->setRubberBand(QChartView::RectangleRubberBand);
    m_chartView->setMinimumSize(320, 200);
    m_chartView->viewport()->setMouseTracking(true);
    m_chartView->viewport()->installEventFilter(this);

    m_cursorLine = new QGraphicsLineItem(m_chart);
    m_cursorLine->setPen(QPen(QColor(0x40, 0x40, 0x40), 1, Qt::DashLine));
    m_cursorLine->setZValue(1000);
    m_cursorLine->hide();
}

void TrendView::buildControls()
{
    m_controls = new TrendControls(this);
    connect(m_controls, &TrendControls::pauseToggled, m_recorder, &TrendRecorder::setPaused);
    connect(m_controls, &TrendControls::resetZoomClicked, this, &TrendView::resetZoom);
    connect(m_controls, &TrendControls::windowChanged, this, &TrendView::onWindowChanged);
    connect(m_controls, &TrendControls::sampleRateChanged, this, &TrendView::sampleRateChanged);
    connect(m_controls, &TrendControls::exportCsvRequested, this, [this](bool whole) {
        exportCsvInteractive(whole ? ExportRange::WholeRecording : ExportRange::VisibleWindow);
    });
    connect(m_controls, &TrendControls::exportPngRequested, this, &TrendView::exportPngInteractive);
}

void TrendView::buildChannelPanel()
{
    m_panel = new TrendChannelPanel(this);
    connect(m_panel, &TrendChannelPanel::visibilityChanged, this, [this](const QString &id, bool) {
        updateSeriesName(id);
        invalidate();
        refreshNow();
    });
    connect(m_panel, &TrendChannelPanel::scaleChanged, this, [this](const QString &id) {
        updateSeriesName(id);
        m_zoomY = false; // the scaled data moved: fit the value axis again
        invalidate();
        refreshNow();
    });
    auto *panelScroll = new QScrollArea(this);
    panelScroll->setWidget(m_panel);
    panelScroll->setWidgetResizable(true);
    panelScroll->setFrameShape(QFrame::NoFrame);
    panelScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_panelScroll = panelScroll;
}

void TrendView::retranslateUi()
{
    m_chartView->setToolTip(tr("Drag to zoom, right click to zoom out"));
    m_axisX->setTitleText(tr("Time [s]"));
    for (const TrendChannel &c : std::as_const(m_channels))
        updateSeriesName(c.id);
    updateCursor();
    updateStatus();
}

void TrendView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void TrendView::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    invalidate();
    m_timer.start();
}

void TrendView::hideEvent(QHideEvent *event)
{
    m_timer.stop();
    QWidget::hideEvent(event);
}

int TrendView::windowSeconds() const
{
    return m_controls->windowSeconds();
}

void TrendView::setWindowSeconds(int seconds)
{
    m_controls->setWindowSeconds(seconds);
}

void TrendView::onWindowChanged()
{
    // The user asked for a window: show it (zoom off).
    resetZoom();
}

double TrendView::sampleRate() const
{
    return m_controls->sampleRate();
}

void TrendView::setSampleRate(double hz)
{
    m_controls->setSampleRate(hz);
}

bool TrendView::isChannelVisible(const QString &id) const
{
    return m_recorder->hasChannel(id) && m_panel->settings(id).visible;
}

void TrendView::setChannelVisible(const QString &id, bool visible)
{
    m_panel->setChannelVisible(id, visible);
}

void TrendView::setChannelScale(const QString &id, double scale, double offset)
{
    m_panel->setChannelScale(id, scale, offset);
}

void TrendView::rebuildSeries()
{
    ++m_updatingAxes;
    m_chart->removeAllSeries();
    m_series.clear();
    m_channels = m_recorder->channels();
    QList<QColor> colors;
    for (const TrendChannel &c : std::as_const(m_channels)) {
        if (!m_colors.contains(c.id)) {
            const QList<QColor> used = m_colors.values();
            QColor pick = seriesColors().at(m_colors.size() % seriesColors().size());
            for (const QColor &p : seriesColors()) {
                if (!used.contains(p)) {
                    pick = p;
                    break;
                }
            }
            m_colors.insert(c.id, pick);
        }
        colors.append(m_colors.value(c.id));
        auto *s = new QLineSeries;
        s->setPen(QPen(m_colors.value(c.id), 1));
        m_chart->addSeries(s);
        s->attachAxis(m_axisX);
        s->attachAxis(m_axisY);
        m_series.insert(c.id, s);
    }
    --m_updatingAxes;
    m_panel->setChannels(m_channels, colors);
    m_panelScroll->setMinimumWidth(m_panel->sizeHint().width()
                                   + m_panelScroll->style()->pixelMetric(QStyle::PM_ScrollBarExtent));
    for (const TrendChannel &c : std::as_const(m_channels))
        updateSeriesName(c.id);
    invalidate();
    refreshNow();
}

void TrendView::updateSeriesName(const QString &id)
{
    QLineSeries *s = m_series.value(id);
    if (!s)
        return;
    const TrendChannelPanel::Settings st = m_panel->settings(id);
    QString name = m_recorder->channel(id).label();
    const QLocale locale;
    if (st.scale != 1.0)
        name += QStringLiteral(" ×") + locale.toString(st.scale, 'g', 6);
    if (st.offset != 0.0)
        name += (st.offset > 0 ? QStringLiteral(" + ") : QStringLiteral(" − "))
            + locale.toString(std::fabs(st.offset), 'g', 6);
    s->setName(name);
    s->setVisible(st.visible);
    const auto markers = m_chart->legend()->markers(s);
    for (QLegendMarker *m : markers)
        m->setVisible(st.visible);

    // Name the value axis after the channel when only one unscaled channel is shown.
    QStringList shown;
    bool scaled = false;
    for (const TrendChannel &c : std::as_const(m_channels)) {
        const TrendChannelPanel::Settings cs = m_panel->settings(c.id);
        if (cs.visible) {
            shown.append(c.label());
            scaled = scaled || cs.scale != 1.0 || cs.offset != 0.0;
        }
    }
    m_axisY->setTitleText(shown.size() == 1 && !scaled ? shown.first() : tr("Scaled value"));
}

int TrendView::plotWidthPx() const
{
    const int w = static_cast<int>(m_chart->plotArea().width());
    return w >= 2 ? w : std::max(2, m_chartView->viewport()->width());
}

void TrendView::computeWindow(qint64 *fromUs, qint64 *toUs) const
{
    if (m_zoomed) {
        *fromUs = m_zoomFromUs;
        *toUs = m_zoomToUs;
        return;
    }
    const qint64 window = qint64(windowSeconds()) * 1000000;
    const qint64 origin = m_recorder->originUs();
    const qint64 end = m_recorder->isPaused() ? m_recorder->pausedAtUs() : m_recorder->lastTimeUs();
    if (end - origin < window) { // a young recording grows from the left edge
        *fromUs = origin;
        *toUs = origin + window;
    } else {
        *fromUs = end - window;
        *toUs = end;
    }
}

void TrendView::refreshNow()
{
    qint64 from = 0;
    qint64 to = 0;
    computeWindow(&from, &to);
    const int width = plotWidthPx();
    if (isDrawn(from, to, width))
        return; // a frozen view only changes when its window, size or settings change
    QElapsedTimer cost;
    cost.start();
    m_drawn = true;
    m_drawnFrom = from;
    m_drawnTo = to;
    m_drawnWidth = width;
    m_drawnState = m_stateVersion;
    m_drawnRevision = m_recorder->revision();
    m_viewFromUs = from;
    m_viewToUs = to;

    // Qt Charts strokes a series' whole outline on every geometry change (replace() and
    // every axis range change), so: build all point lists, empty the series (cheap) if an
    // axis moves, move the axes, then replace() each series once.
    double yMin = std::numeric_limits<double>::infinity();
    double yMax = -std::numeric_limits<double>::infinity();
    ++m_updatingAxes;
    const SeriesPoints updates = decimate(from, to, width, &yMin, &yMax);
    moveAxes(from, to, yMin, yMax, updates);
    for (const auto &u : updates)
        u.first->replace(u.second); // never append() in a loop: quadratic in Qt Charts
    --m_updatingAxes;
    updateCursor();
    updateStatus();
    // Keep redrawing under ~25 % of the GUI thread: slow down on a slow machine (the
    // render that follows costs about as much again), speed up again when it is fast.
    const int interval = std::clamp(int(cost.elapsed()) * 4, RefreshIntervalMs, SlowestRefreshIntervalMs);
    if (interval != m_timer.interval())
        m_timer.setInterval(interval);
}

bool TrendView::isDrawn(qint64 fromUs, qint64 toUs, int width) const
{
    const bool live = !m_recorder->isPaused() && !m_zoomed;
    return m_drawn && fromUs == m_drawnFrom && toUs == m_drawnTo && width == m_drawnWidth
        && m_stateVersion == m_drawnState && (!live || m_recorder->revision() == m_drawnRevision);
}

TrendView::SeriesPoints TrendView::decimate(qint64 fromUs, qint64 toUs, int width, double *yMin, double *yMax)
{
    SeriesPoints updates;
    for (const TrendChannel &c : std::as_const(m_channels)) {
        QLineSeries *s = m_series.value(c.id);
        const SampleBuffer *buf = m_recorder->buffer(c.id);
        const TrendChannelPanel::Settings st = m_panel->settings(c.id);
        if (!s || !buf)
            continue;
        if (!st.visible) {
            if (s->count() > 0)
                s->clear();
            continue;
        }
        TrendPlotBuilder::Result r = TrendPlotBuilder::build(*buf, fromUs, toUs, width, m_recorder->originUs(),
                                                             st.scale, st.offset);
        if (r.hasData()) {
            *yMin = std::min(*yMin, r.yMin);
            *yMax = std::max(*yMax, r.yMax);
        }
        updates.append({s, std::move(r.points)});
    }
    return updates;
}

void TrendView::moveAxes(qint64 fromUs, qint64 toUs, double yMin, double yMax, const SeriesPoints &updates)
{
    const double o = static_cast<double>(m_recorder->originUs());
    const double xMin = (static_cast<double>(fromUs) - o) * 1e-6;
    const double xMax = (static_cast<double>(toUs) - o) * 1e-6;
    std::optional<std::pair<double, double>> yRange;
    if (m_zoomY)
        yRange = std::make_pair(m_zoomYMin, m_zoomYMax);
    else if (yMin <= yMax)
        yRange = TrendAxisScale::fitValueRange(yMin, yMax, m_axisY->min(), m_axisY->max());
    const bool yMoves = yRange && (yRange->first != m_axisY->min() || yRange->second != m_axisY->max());
    if (xMin != m_axisX->min() || xMax != m_axisX->max() || yMoves) {
        for (const auto &u : updates) {
            if (u.first->count() > 0)
                u.first->clear();
        }
    }
    const double step = TrendAxisScale::niceStep((xMax - xMin) / 6.0);
    if (step != m_axisX->tickInterval())
        m_axisX->setTickInterval(step);
    m_axisX->setRange(xMin, xMax);
    if (yMoves) {
        m_axisY->setRange(yRange->first, yRange->second);
        if (!m_zoomY)
            m_axisY->applyNiceNumbers();
    }
}

void TrendView::onAxisRangeChanged()
{
    if (m_updatingAxes > 0)
        return; // our own refresh
    // The user zoomed (rubber band or right click): freeze on the axes' ranges.
    const qint64 origin = m_recorder->originUs();
    m_zoomed = true;
    m_zoomFromUs = origin + secondsToUs(m_axisX->min());
    m_zoomToUs = std::max(m_zoomFromUs, origin + secondsToUs(m_axisX->max()));
    m_zoomY = true;
    m_zoomYMin = m_axisY->min();
    m_zoomYMax = m_axisY->max();
    m_controls->setZoomed(true);
    if (!m_recorder->isPaused()) {
        // No redraw from onPausedChanged() now: QChart is between setting the two axes.
        m_handlingZoom = true;
        m_recorder->setPaused(true);
        m_handlingZoom = false;
    }
    invalidate();
    // Redraw with full resolution for the new range once the zoom has set both axes.
    QTimer::singleShot(0, this, &TrendView::refreshNow);
}

void TrendView::resetZoom()
{
    dropZoom();
    invalidate();
    refreshNow();
}

void TrendView::dropZoom()
{
    m_zoomed = false;
    m_zoomY = false;
    m_controls->setZoomed(false);
}

void TrendView::onPausedChanged(bool paused)
{
    m_controls->setPaused(paused);
    if (!paused) // back to live: drop the zoom
        dropZoom();
    invalidate();
    if (!m_handlingZoom)
        refreshNow();
}

bool TrendView::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_chartView->viewport()) {
        if (event->type() == QEvent::MouseMove)
            setCursorPosition(static_cast<QMouseEvent *>(event)->position().toPoint());
        else if (event->type() == QEvent::Leave)
            hideCursor();
    }
    return QWidget::eventFilter(watched, event);
}

void TrendView::setCursorPosition(const QPoint &viewportPos)
{
    m_cursorPos = viewportPos;
    updateCursor();
}

void TrendView::hideCursor()
{
    m_cursorPos.reset();
    updateCursor();
}

std::optional<double> TrendView::timeAtViewportX(int x) const
{
    const QRectF plot = m_chart->plotArea();
    const QPointF chartPos = m_chart->mapFromScene(m_chartView->mapToScene(QPoint(x, 0)));
    if (plot.width() <= 0 || chartPos.x() < plot.left() || chartPos.x() > plot.right())
        return std::nullopt;
    const double f = (chartPos.x() - plot.left()) / plot.width();
    return m_axisX->min() + f * (m_axisX->max() - m_axisX->min());
}

void TrendView::updateCursor()
{
    const QRectF plot = m_chart->plotArea();
    std::optional<double> t;
    if (m_cursorPos) {
        const QPointF chartPos = m_chart->mapFromScene(m_chartView->mapToScene(*m_cursorPos));
        if (plot.contains(chartPos))
            t = timeAtViewportX(m_cursorPos->x());
    }
    if (!t) {
        m_cursorLine->hide();
        m_readout->setText(tr("Point at the plot to read values."));
        return;
    }
    const double x = m_chart->mapFromScene(m_chartView->mapToScene(*m_cursorPos)).x();
    m_cursorLine->setLine(x, plot.top(), x, plot.bottom());
    m_cursorLine->show();

    const QLocale locale;
    const qint64 tUs = m_recorder->originUs() + secondsToUs(*t);
    QStringList parts{tr("t = %1 s").arg(locale.toString(*t, 'f', 3))};
    for (const TrendChannel &c : std::as_const(m_channels)) {
        if (!m_panel->settings(c.id).visible)
            continue;
        const SampleBuffer *buf = m_recorder->buffer(c.id);
        QString value = tr("–");
        if (buf && !buf->isEmpty() && tUs >= buf->firstTimeUs() && tUs <= buf->lastTimeUs()) {
            if (const auto s = buf->nearest(tUs))
                value = locale.toString(s->value, 'f', c.decimals);
        }
        const QString name = c.name.isEmpty() ? c.id : c.name;
        parts.append(c.unit.isEmpty() ? tr("%1: %2").arg(name, value) : tr("%1: %2 %3").arg(name, value, c.unit));
    }
    m_readout->setText(parts.join(QStringLiteral("   ")));
}

QString TrendView::cursorReadout() const
{
    return m_readout->text();
}

void TrendView::updateStatus()
{
    qsizetype n = 0;
    for (const TrendChannel &c : std::as_const(m_channels)) {
        if (const SampleBuffer *b = m_recorder->buffer(c.id))
            n += b->size();
    }
    QString text = tr("%Ln sample(s) recorded", nullptr, static_cast<int>(std::min<qsizetype>(n, INT_MAX)));
    if (m_recorder->droppedCount() > 0)
        text += QStringLiteral(" · ") + tr("recording limit reached: oldest samples dropped");
    if (m_recorder->isPaused())
        text += QStringLiteral(" · ") + tr("view paused, still recording");
    m_status->setText(text);
}

QStringList TrendView::exportChannelIds() const
{
    QStringList ids;
    for (const TrendChannel &c : std::as_const(m_channels)) {
        if (m_panel->settings(c.id).visible)
            ids.append(c.id);
    }
    return ids.isEmpty() ? m_recorder->channelIds() : ids;
}

Error TrendView::exportCsv(const QString &path, ExportRange range) const
{
    const QStringList ids = exportChannelIds();
    const TrendSnapshot snap = range == ExportRange::WholeRecording
        ? m_recorder->snapshotAll(ids)
        : m_recorder->snapshot(m_viewFromUs, m_viewToUs, ids);
    return CsvWriter::save(path, snap);
}

Error TrendView::exportPng(const QString &path) const
{
    const QPixmap image = m_chartView->grab();
    QSaveFile file(path);
    if (image.isNull() || !file.open(QIODevice::WriteOnly) || !image.save(&file, "PNG") || !file.commit()) {
        return Error{ErrorCode::FileError,
                     tr("Cannot save the plot image %1: %2. Check that the folder exists and "
                        "is writable.")
                         .arg(path, file.errorString()),
                     0};
    }
    return Error::none();
}

QString TrendView::askSavePath(const QString &title, const QString &suffix, const QString &filter)
{
    const QString name = QStringLiteral("trend-%1.%2")
                             .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")), suffix);
    return QFileDialog::getSaveFileName(this, title, QDir::home().filePath(name), filter);
}

void TrendView::exportCsvInteractive(ExportRange range)
{
    const QString path = askSavePath(tr("Export trend as CSV"), QStringLiteral("csv"), tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    if (const Error e = exportCsv(path, range))
        QMessageBox::warning(this, tr("Export CSV"), e.message);
}

void TrendView::exportPngInteractive()
{
    const QString path = askSavePath(tr("Export plot as PNG"), QStringLiteral("png"), tr("PNG images (*.png)"));
    if (path.isEmpty())
        return;
    if (const Error e = exportPng(path))
        QMessageBox::warning(this, tr("Export PNG"), e.message);
}

} // namespace dd
