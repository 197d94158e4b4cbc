#include "ui/panels/trend/trendview.h"

#include "core/trend/csvwriter.h"
#include "core/trend/trendaxisscale.h"
#include "core/trend/trendplotbuilder.h"
#include "core/trend/trendrecorder.h"
#include "ui/common/displaytext.h"
#include "ui/panels/trend/trendchannelpanel.h"
#include "ui/panels/trend/trendcontrols.h"
#include "ui/panels/trend/trendplot.h"

#include <QBuffer>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QImage>
#include <QLabel>
#include <QLocale>
#include <QPainter>
#include <QSaveFile>
#include <QSvgGenerator>
#include <QVBoxLayout>
#include <climits>
#include <cmath>

namespace dd {

namespace {

constexpr int RefreshIntervalMs = 40;         // 25 Hz
constexpr int SlowestRefreshIntervalMs = 200; // 5 Hz on a machine too slow for 25

// Distinguishable on white and in grey-scale print.
const QList<QColor> &seriesColors()
{
    static const QList<QColor> colors{QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28), QColor(0x2c, 0xa0, 0x2c),
                                      QColor(0xff, 0x7f, 0x0e), QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                                      QColor(0x17, 0xbe, 0xcf), QColor(0x7f, 0x7f, 0x7f), QColor(0xe3, 0x77, 0xc2),
                                      QColor(0xbc, 0xbd, 0x22)};
    return colors;
}

qint64 secondsToUs(double s)
{
    return static_cast<qint64>(std::llround(s * 1e6));
}

// The range an axis shows for data spanning [lo, hi]: fitted with hysteresis, then widened
// to whole ticks so the labels are round.
std::pair<double, double> niceRange(double lo, double hi, const std::pair<double, double> &current)
{
    const auto fitted = TrendAxisScale::fitValueRange(lo, hi, current.first, current.second);
    if (fitted == current)
        return current;
    const double step = TrendAxisScale::niceStep((fitted.second - fitted.first) / 5.0);
    return {std::floor(fitted.first / step) * step, std::ceil(fitted.second / step) * step};
}

} // namespace

TrendView::TrendView(TrendRecorder *recorder, QWidget *parent)
    : QWidget(parent)
    , m_recorder(recorder)
{
    buildUi();
    m_timer.setInterval(RefreshIntervalMs);
    connect(&m_timer, &QTimer::timeout, this, &TrendView::refreshNow);
    connect(m_recorder, &TrendRecorder::channelsChanged, this, &TrendView::onChannelsChanged);
    connect(m_recorder, &TrendRecorder::pausedChanged, this, &TrendView::onPausedChanged);
    connect(m_recorder, &TrendRecorder::cleared, this, [this] {
        dropZoom();
        m_markers = {};
        m_plot->setMarker(0, std::nullopt);
        m_plot->setMarker(1, std::nullopt);
        invalidate();
    });
    onChannelsChanged();
    onPausedChanged(m_recorder->isPaused());
    retranslateUi();
}

TrendView::~TrendView() = default;

void TrendView::buildUi()
{
    m_controls = new TrendControls(this);
    connect(m_controls, &TrendControls::recordToggled, this, &TrendView::recordToggled);
    connect(m_controls, &TrendControls::pauseToggled, m_recorder, &TrendRecorder::setPaused);
    connect(m_controls, &TrendControls::resetZoomClicked, this, &TrendView::resetZoom);
    connect(m_controls, &TrendControls::windowChanged, this, &TrendView::onWindowChanged);
    connect(m_controls, &TrendControls::sampleRateChanged, this, &TrendView::sampleRateChanged);
    connect(m_controls, &TrendControls::exportCsvRequested, this, [this](bool whole) {
        exportCsvInteractive(whole ? ExportRange::WholeRecording : ExportRange::VisibleWindow);
    });
    connect(m_controls, &TrendControls::exportPngRequested, this, [this] { exportImageInteractive(false); });
    connect(m_controls, &TrendControls::exportSvgRequested, this, [this] { exportImageInteractive(true); });

    m_plot = new TrendPlot(this);
    m_plot->setObjectName(QStringLiteral("trendPlot"));
    connectPlot();

    m_panel = new TrendChannelPanel(this);
    connect(m_panel, &TrendChannelPanel::visibilityChanged, this, [this] {
        assignColors();
        invalidate();
        refreshNow();
    });
    connect(m_panel, &TrendChannelPanel::scaleChanged, this, [this](const QString &id) {
        m_zoomY[static_cast<size_t>(channelAxis(id))].reset(); // the scaled data moved: fit again
        invalidate();
        refreshNow();
    });
    connect(m_panel, &TrendChannelPanel::axisChanged, this, [this] {
        m_zoomY = {};
        invalidate();
        refreshNow();
    });

    const auto wrapping = [this] {
        auto *l = new QLabel(this);
        l->setWordWrap(true);
        l->setTextInteractionFlags(Qt::TextSelectableByMouse);
        l->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
        return l;
    };
    m_readout = wrapping();
    m_markerReadout = wrapping();
    m_message = wrapping();
    m_status = wrapping();
    m_status->setAlignment(Qt::AlignRight | Qt::AlignVCenter);

    auto *plotRow = new QHBoxLayout;
    plotRow->addWidget(m_plot, 1);
    plotRow->addWidget(m_panel);
    auto *bottom = new QHBoxLayout;
    bottom->addWidget(m_message, 3);
    bottom->addWidget(m_status, 2);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_controls);
    layout->addLayout(plotRow, 1);
    layout->addWidget(m_readout);
    layout->addWidget(m_markerReadout);
    layout->addLayout(bottom);
}

void TrendView::connectPlot()
{
    connect(m_plot, &TrendPlot::hoverMoved, this, [this](double t) { setHoverTime(t); });
    connect(m_plot, &TrendPlot::hoverLeft, this, [this] { setHoverTime(std::nullopt); });
    connect(m_plot, &TrendPlot::markerPlaced, this, &TrendView::setMarker);
    connect(m_plot, &TrendPlot::markersCleared, this, [this] {
        setMarker(0, std::nullopt);
        setMarker(1, std::nullopt);
    });
    connect(m_plot, &TrendPlot::zoomToRect, this, &TrendView::zoomToRect);
    connect(m_plot, &TrendPlot::zoomBy, this, &TrendView::zoomAround);
    connect(m_plot, &TrendPlot::panBy, this, &TrendView::pan);
    connect(m_plot, &TrendPlot::resetRequested, this, &TrendView::resetZoom);
}

void TrendView::retranslateUi()
{
    m_plot->setToolTip(tr("Drag: zoom · wheel: zoom time (Shift: pan) · click: cursor A, Shift+click: "
                          "cursor B · +/−, ←/→, Home: zoom, pan, reset · Del: remove cursors"));
    m_plot->setTimeTitle(tr("Time [s]"));
    invalidate();
    refreshNow();
    updateReadouts();
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
    resetZoom(); // the user asked for a window: show it
}

double TrendView::sampleRate() const
{
    return m_controls->sampleRate();
}

void TrendView::setSampleRate(double hz)
{
    m_controls->setSampleRate(hz);
}

void TrendView::setRecording(bool recording)
{
    m_controls->setRecording(recording);
    updateStatus();
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

void TrendView::setChannelAxis(const QString &id, int axis)
{
    m_panel->setChannelAxis(id, axis);
}

int TrendView::channelAxis(const QString &id) const
{
    return m_panel->settings(id).axis;
}

void TrendView::onChannelsChanged()
{
    m_channels = m_recorder->channels();
    m_decimation.clear();
    m_panel->setChannels(m_channels);
    assignColors();
    invalidate();
    refreshNow();
}

void TrendView::assignColors()
{
    // No two shown channels alike: a shown channel keeps its colour unless an earlier shown
    // one has it; then it takes the first free one of the palette (then generated hues).
    QList<QColor> taken;
    const auto freeColor = [&taken] {
        for (const QColor &c : seriesColors())
            if (!taken.contains(c))
                return c;
        for (int i = 0;; ++i) {
            const QColor c = QColor::fromHsv((i * 47 + 15) % 360, 200, 170 + (i % 3) * 30);
            if (!taken.contains(c))
                return c;
        }
    };
    for (const TrendChannel &c : std::as_const(m_channels)) {
        if (!m_panel->settings(c.id).visible)
            continue;
        if (!m_colors.contains(c.id) || taken.contains(m_colors.value(c.id)))
            m_colors.insert(c.id, freeColor());
        taken.append(m_colors.value(c.id));
    }
    for (const TrendChannel &c : std::as_const(m_channels))
        if (!m_colors.contains(c.id)) // hidden: a colour for the list, checked again when shown
            m_colors.insert(c.id, freeColor());
    m_panel->setColors(m_colors);
}

QString TrendView::seriesLabel(const TrendChannel &c) const
{
    const TrendChannelPanel::Settings st = m_panel->settings(c.id);
    QString name = DisplayText::channelLabel(c.name.isEmpty() ? c.id : c.name, c.unit);
    const QLocale locale;
    if (st.scale != 1.0)
        name += QStringLiteral(" ×") + locale.toString(st.scale, 'g', 6);
    if (st.offset != 0.0)
        name += (st.offset > 0 ? QStringLiteral(" + ") : QStringLiteral(" − "))
            + locale.toString(std::fabs(st.offset), 'g', 6);
    return st.axis == 0 ? tr("%1 (left)").arg(name) : tr("%1 (right)").arg(name);
}

QString TrendView::axisTitle(int axis) const
{
    // The unit(s) of the channels on the axis; the channel's label when it is alone.
    QStringList labels;
    QStringList units;
    bool scaled = false;
    for (const TrendChannel &c : std::as_const(m_channels)) {
        const TrendChannelPanel::Settings st = m_panel->settings(c.id);
        if (!st.visible || st.axis != axis)
            continue;
        labels.append(DisplayText::channelLabel(c.name.isEmpty() ? c.id : c.name, c.unit));
        const QString unit = c.unit.isEmpty() ? tr("no unit") : DisplayText::unit(c.unit);
        if (!units.contains(unit))
            units.append(unit);
        scaled = scaled || st.scale != 1.0 || st.offset != 0.0;
    }
    if (labels.isEmpty())
        return QString();
    if (scaled)
        return tr("Scaled value");
    if (labels.size() == 1)
        return labels.first();
    return units.join(QStringLiteral(", "));
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

bool TrendView::isDrawn(qint64 fromUs, qint64 toUs, int width) const
{
    const bool live = !m_recorder->isPaused() && !m_zoomed;
    return m_drawn && fromUs == m_drawnFrom && toUs == m_drawnTo && width == m_drawnWidth
        && m_stateVersion == m_drawnState && (!live || m_recorder->revision() == m_drawnRevision);
}

void TrendView::refreshNow()
{
    qint64 from = 0;
    qint64 to = 0;
    computeWindow(&from, &to);
    const int width = std::max(2, static_cast<int>(m_plot->plotRect().width()));
    if (isDrawn(from, to, width))
        return;
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

    std::array<double, 2> lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    std::array<double, 2> hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    std::array<bool, 2> used{false, false};
    QList<TrendPlot::Series> series;
    const qint64 origin = m_recorder->originUs();
    for (const TrendChannel &c : std::as_const(m_channels)) {
        const TrendChannelPanel::Settings st = m_panel->settings(c.id);
        const SampleBuffer *buf = m_recorder->buffer(c.id);
        if (!st.visible || !buf)
            continue;
        const size_t a = st.axis == 0 ? 0 : 1;
        used[a] = true;
        TrendPlotBuilder::Result r = TrendPlotBuilder::build(*buf, from, to, width, origin, st.scale, st.offset,
                                                             &m_decimation[c.id]);
        if (r.hasData()) {
            lo[a] = std::min(lo[a], r.yMin);
            hi[a] = std::max(hi[a], r.yMax);
        }
        series.append(TrendPlot::Series{c.id, seriesLabel(c), m_colors.value(c.id), int(a), std::move(r.points)});
    }
    for (size_t a = 0; a < 2; ++a) {
        if (m_zoomY[a])
            m_axisRange[a] = *m_zoomY[a];
        else if (lo[a] <= hi[a])
            m_axisRange[a] = niceRange(lo[a], hi[a], m_axisRange[a]);
        TrendPlot::ValueAxis axis;
        axis.used = used[a];
        axis.min = m_axisRange[a].first;
        axis.max = m_axisRange[a].second;
        axis.title = axisTitle(int(a));
        m_plot->setValueAxis(int(a), axis);
    }
    m_plot->setTimeRange(double(from - origin) * 1e-6, double(to - origin) * 1e-6);
    m_plot->setSeries(series);
    updateReadouts();
    updateStatus();
    // Keep redrawing under ~25 % of the GUI thread: slow down on a slow machine (the
    // paint that follows costs about as much again), speed up again when it is fast.
    const int interval = std::clamp(int(cost.elapsed()) * 4, RefreshIntervalMs, SlowestRefreshIntervalMs);
    if (interval != m_timer.interval())
        m_timer.setInterval(interval);
}

void TrendView::enterZoom(qint64 fromUs, qint64 toUs)
{
    if (toUs <= fromUs)
        toUs = fromUs + 1000; // 1 ms at least
    m_zoomed = true;
    m_zoomFromUs = fromUs;
    m_zoomToUs = toUs;
    m_controls->setZoomed(true);
    if (!m_recorder->isPaused()) {
        m_handlingZoom = true;
        m_recorder->setPaused(true); // zooming stops following
        m_handlingZoom = false;
    }
    invalidate();
    refreshNow();
}

void TrendView::zoomTime(qint64 fromUs, qint64 toUs)
{
    enterZoom(fromUs, toUs);
}

void TrendView::zoomAround(double factor, double anchorS)
{
    const qint64 anchor = usAt(anchorS);
    const qint64 from = anchor - qint64(std::llround(double(anchor - m_viewFromUs) * factor));
    const qint64 to = anchor + qint64(std::llround(double(m_viewToUs - anchor) * factor));
    enterZoom(from, to);
}

void TrendView::pan(double fraction)
{
    const qint64 shift = qint64(std::llround(double(m_viewToUs - m_viewFromUs) * fraction));
    enterZoom(m_viewFromUs + shift, m_viewToUs + shift);
}

void TrendView::zoomToRect(const QRectF &r)
{
    for (int a = 0; a < 2; ++a) {
        if (m_plot->valueAxis(a).used)
            m_zoomY[static_cast<size_t>(a)] = std::make_pair(m_plot->valueAtY(a, r.bottom()),
                                                             m_plot->valueAtY(a, r.top()));
    }
    enterZoom(usAt(m_plot->timeAtX(r.left())), usAt(m_plot->timeAtX(r.right())));
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
    m_zoomY = {};
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

qint64 TrendView::usAt(double seconds) const
{
    return m_recorder->originUs() + secondsToUs(seconds);
}

QString TrendView::valueText(const TrendChannel &c, std::optional<double> v) const
{
    const QString value = v ? QLocale().toString(*v, 'f', c.decimals) : tr("–");
    const QString name = c.name.isEmpty() ? c.id : c.name;
    return c.unit.isEmpty() ? tr("%1: %2").arg(name, value)
                            : tr("%1: %2 %3").arg(name, value, DisplayText::unit(c.unit));
}

void TrendView::setHoverTime(std::optional<double> timeS)
{
    m_hover = timeS;
    m_plot->setHoverTime(timeS);
    updateReadouts();
}

void TrendView::setMarker(int which, std::optional<double> timeS)
{
    m_markers[static_cast<size_t>(which)] = timeS;
    m_plot->setMarker(which, timeS);
    updateReadouts();
}

void TrendView::updateReadouts()
{
    const QLocale locale;
    if (!m_hover) {
        m_readout->setText(tr("Point at the plot to read values; click to set cursor A, Shift+click for B."));
    } else {
        const qint64 tUs = usAt(*m_hover);
        QStringList parts{tr("t = %1 s").arg(locale.toString(*m_hover, 'f', 3))};
        for (const TrendChannel &c : std::as_const(m_channels)) {
            if (m_panel->settings(c.id).visible)
                parts.append(valueText(c, m_recorder->lineValueAt(c.id, tUs)));
        }
        m_readout->setText(parts.join(QStringLiteral("   ")));
    }

    const auto &a = m_markers[0];
    const auto &b = m_markers[1];
    if (!a && !b) {
        m_markerReadout->clear();
        m_markerReadout->hide();
        return;
    }
    QStringList parts;
    if (a)
        parts.append(tr("A: %1 s").arg(locale.toString(*a, 'f', 3)));
    if (b)
        parts.append(tr("B: %1 s").arg(locale.toString(*b, 'f', 3)));
    if (a && b) {
        parts.append(tr("Δt = %1 s").arg(locale.toString(*b - *a, 'f', 3)));
        for (const TrendChannel &c : std::as_const(m_channels)) {
            if (!m_panel->settings(c.id).visible)
                continue;
            const auto va = m_recorder->lineValueAt(c.id, usAt(*a));
            const auto vb = m_recorder->lineValueAt(c.id, usAt(*b));
            const std::optional<double> d = va && vb ? std::optional<double>(*vb - *va) : std::nullopt;
            const QString name = c.name.isEmpty() ? c.id : c.name;
            const QString value = d ? locale.toString(*d, 'f', c.decimals) : tr("–");
            parts.append(c.unit.isEmpty() ? tr("Δ %1: %2").arg(name, value)
                                          : tr("Δ %1: %2 %3").arg(name, value, DisplayText::unit(c.unit)));
        }
    }
    m_markerReadout->setText(parts.join(QStringLiteral("   ")));
    m_markerReadout->show();
}

QString TrendView::cursorReadout() const
{
    return m_readout->text();
}

QString TrendView::markerReadout() const
{
    return m_markerReadout->text();
}

QString TrendView::message() const
{
    return m_message->text();
}

void TrendView::showMessage(const QString &text, bool problem)
{
    m_message->setText(text);
    m_message->setStyleSheet(problem ? QStringLiteral("color: #b00020;") : QString());
}

void TrendView::updateStatus()
{
    qsizetype n = 0;
    for (const TrendChannel &c : std::as_const(m_channels)) {
        if (const SampleBuffer *b = m_recorder->buffer(c.id))
            n += b->size() - b->gapCount();
    }
    QString text = tr("%Ln sample(s) recorded", nullptr, static_cast<int>(std::min<qsizetype>(n, INT_MAX)));
    if (m_controls->isRecording())
        text += QStringLiteral(" · ") + tr("recording");
    if (m_recorder->droppedCount() > 0)
        text += QStringLiteral(" · ") + tr("recording limit reached: oldest samples dropped");
    if (m_recorder->isPaused())
        text += QStringLiteral(" · ") + tr("view paused");
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

QStringList TrendView::titleBlock() const
{
    const QLocale locale;
    QStringList lines;
    lines.append(m_driveTitle.isEmpty() ? tr("DriveDesk trend") : tr("DriveDesk trend: %1").arg(m_driveTitle));
    const QDateTime start = QDateTime::fromMSecsSinceEpoch(m_recorder->originUs() / 1000);
    lines.append(tr("Recorded %1, window %2 s to %3 s")
                     .arg(locale.toString(start, QLocale::ShortFormat),
                          locale.toString(double(m_viewFromUs - m_recorder->originUs()) * 1e-6, 'f', 3),
                          locale.toString(double(m_viewToUs - m_recorder->originUs()) * 1e-6, 'f', 3)));
    QStringList channels;
    for (const TrendChannel &c : std::as_const(m_channels))
        if (m_panel->settings(c.id).visible)
            channels.append(seriesLabel(c));
    lines.append(tr("Channels: %1").arg(channels.join(QStringLiteral("; "))));
    return lines;
}

int TrendView::titleBlockHeight(int width) const
{
    const QFontMetrics fm(m_plot->font());
    const QRect r = fm.boundingRect(QRect(0, 0, width - 12, 10000), Qt::TextWordWrap,
                                    titleBlock().join(QLatin1Char('\n')));
    return r.height() + 12;
}

void TrendView::renderExport(QPainter *painter, const QSize &size) const
{
    const int head = titleBlockHeight(size.width());
    painter->fillRect(QRect(QPoint(0, 0), size), Qt::white);
    painter->setFont(m_plot->font());
    painter->setPen(Qt::black);
    painter->drawText(QRect(6, 6, size.width() - 12, head - 6), Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop,
                      titleBlock().join(QLatin1Char('\n')));
    m_plot->render(painter, QRectF(0, head, m_plot->width(), m_plot->height()));
}

Error TrendView::exportPng(const QString &path) const
{
    const QSize size(m_plot->width(), m_plot->height() + titleBlockHeight(m_plot->width()));
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    {
        QPainter p(&image);
        renderExport(&p, size);
    }
    QSaveFile file(path);
    if (image.isNull() || !file.open(QIODevice::WriteOnly) || !image.save(&file, "PNG") || !file.commit()) {
        return Error{ErrorCode::FileError,
                     tr("Cannot save the plot image %1: %2. Check that the folder exists and is writable.")
                         .arg(path, file.errorString()),
                     0};
    }
    return Error::none();
}

Error TrendView::exportSvg(const QString &path) const
{
    const QSize size(m_plot->width(), m_plot->height() + titleBlockHeight(m_plot->width()));
    QBuffer buffer;
    buffer.open(QIODevice::WriteOnly);
    {
        QSvgGenerator svg;
        svg.setOutputDevice(&buffer);
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setTitle(titleBlock().value(0));
        svg.setDescription(titleBlock().join(QLatin1Char('\n')));
        QPainter p(&svg);
        renderExport(&p, size);
    }
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(buffer.data()) != buffer.size() || !file.commit()) {
        return Error{ErrorCode::FileError,
                     tr("Cannot save the plot image %1: %2. Check that the folder exists and is writable.")
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
    if (!path.isEmpty())
        exportFile(range == ExportRange::WholeRecording ? ExportKind::CsvWhole : ExportKind::CsvWindow, path);
}

void TrendView::exportImageInteractive(bool svg)
{
    const QString path = svg ? askSavePath(tr("Export plot as SVG"), QStringLiteral("svg"), tr("SVG images (*.svg)"))
                             : askSavePath(tr("Export plot as PNG"), QStringLiteral("png"), tr("PNG images (*.png)"));
    if (!path.isEmpty())
        exportFile(svg ? ExportKind::Svg : ExportKind::Png, path);
}

bool TrendView::exportFile(ExportKind kind, const QString &path)
{
    Error e;
    switch (kind) {
    case ExportKind::CsvWhole: e = exportCsv(path, ExportRange::WholeRecording); break;
    case ExportKind::CsvWindow: e = exportCsv(path, ExportRange::VisibleWindow); break;
    case ExportKind::Png: e = exportPng(path); break;
    case ExportKind::Svg: e = exportSvg(path); break;
    }
    if (e) {
        showMessage(e.message, true);
        return false;
    }
    const QString shown = QDir::toNativeSeparators(QFileInfo(path).absoluteFilePath());
    showMessage(kind == ExportKind::CsvWhole || kind == ExportKind::CsvWindow ? tr("CSV saved to %1.").arg(shown)
                                                                              : tr("Plot saved to %1.").arg(shown),
                false);
    emit fileWritten(path);
    return true;
}

} // namespace dd
