#include "ui/panels/tuning/captureplot.h"

#include "ui/panels/trend/trendplot.h"

#include <QEvent>
#include <QLabel>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>

namespace dd {

CapturePlot::CapturePlot(QWidget *parent)
    : QWidget(parent)
    , m_plot(new TrendPlot(this))
    , m_readout(new QLabel(this))
{
    m_plot->setObjectName(QStringLiteral("capturePlot"));
    m_plot->setMinimumSize(240, 160);
    m_readout->setObjectName(QStringLiteral("captureCursorReadout"));
    m_readout->setWordWrap(true);
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plot, 1);
    layout->addWidget(m_readout);

    connect(m_plot, &TrendPlot::markerPlaced, this, [this](int which, double t) { setMarker(which, t); });
    connect(m_plot, &TrendPlot::markersCleared, this, [this] {
        setMarker(0, std::nullopt);
        setMarker(1, std::nullopt);
    });
    connect(m_plot, &TrendPlot::resetRequested, this, &CapturePlot::resetZoom);
    connect(m_plot, &TrendPlot::zoomBy, this, [this](double factor, double anchor) {
        setTimeWindow(anchor - (anchor - m_fromS) * factor, anchor + (m_toS - anchor) * factor);
    });
    connect(m_plot, &TrendPlot::panBy, this, [this](double fraction) {
        const double d = (m_toS - m_fromS) * fraction;
        setTimeWindow(m_fromS + d, m_toS + d);
    });
    connect(m_plot, &TrendPlot::zoomToRect, this,
            [this](const QRectF &r) { setTimeWindow(m_plot->timeAtX(r.left()), m_plot->timeAtX(r.right())); });
    changeEvent(nullptr);
    updateReadout();
}

void CapturePlot::setCurves(const QList<Curve> &curves, const QString &valueTitle)
{
    m_curves = curves;
    m_valueTitle = valueTitle;
    if (!m_zoomed)
        fitTime();
    rebuild();
    updateReadout();
}

void CapturePlot::fitTime()
{
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const Curve &c : std::as_const(m_curves)) {
        if (c.time.isEmpty())
            continue;
        lo = std::min(lo, c.time.first());
        hi = std::max(hi, c.time.last());
    }
    if (!(hi > lo)) {
        lo = 0.0;
        hi = 1.0;
    }
    m_fromS = lo;
    m_toS = hi;
}

void CapturePlot::resetZoom()
{
    m_zoomed = false;
    fitTime();
    rebuild();
}

void CapturePlot::setTimeWindow(double fromS, double toS)
{
    if (!(toS > fromS) || !std::isfinite(fromS) || !std::isfinite(toS))
        return;
    m_zoomed = true;
    m_fromS = fromS;
    m_toS = toS;
    rebuild();
}

QList<QPointF> CapturePlot::decimate(const QVector<double> &time, const QVector<double> &values, double fromS,
                                     double toS, int columns)
{
    QList<QPointF> out;
    const qsizetype n = std::min(time.size(), values.size());
    if (n == 0 || !(toS > fromS))
        return out;
    columns = std::max(1, columns);
    // The first sample inside the window, and one before it so the line reaches the edge.
    qsizetype i = std::lower_bound(time.begin(), time.begin() + n, fromS) - time.begin();
    if (i > 0)
        --i;
    const double perColumn = columns / (toS - fromS);
    out.reserve(std::min<qsizetype>(n - i, 2 * columns + 4));
    int bucket = std::numeric_limits<int>::min();
    qsizetype lo = -1, hi = -1;
    auto flush = [&] {
        if (lo < 0)
            return;
        const qsizetype a = std::min(lo, hi), b = std::max(lo, hi);
        out.append(QPointF(time[a], values[a]));
        if (b != a)
            out.append(QPointF(time[b], values[b]));
        lo = hi = -1;
    };
    for (; i < n; ++i) {
        const double t = time[i];
        const double v = values[i];
        if (std::isnan(v)) {
            flush();
            out.append(QPointF(t, v)); // a break
            continue;
        }
        const int b = t < fromS ? -1 : t > toS ? columns : int((t - fromS) * perColumn);
        if (b != bucket) {
            flush();
            bucket = b;
        }
        if (lo < 0 || v < values[lo])
            lo = i;
        if (hi < 0 || v > values[hi])
            hi = i;
        if (t > toS)
            break; // the one sample after the window
    }
    flush();
    return out;
}

std::optional<double> CapturePlot::valueAt(const QVector<double> &time, const QVector<double> &values, double t)
{
    const qsizetype n = std::min(time.size(), values.size());
    if (n == 0 || t < time.first() || t > time[n - 1])
        return std::nullopt;
    qsizetype i = std::lower_bound(time.begin(), time.begin() + n, t) - time.begin();
    if (i >= n)
        i = n - 1;
    if (time[i] == t || i == 0)
        return std::isnan(values[i]) ? std::nullopt : std::optional<double>(values[i]);
    const double t0 = time[i - 1], t1 = time[i], v0 = values[i - 1], v1 = values[i];
    if (std::isnan(v0) || std::isnan(v1))
        return std::nullopt;
    return t1 > t0 ? v0 + (v1 - v0) * (t - t0) / (t1 - t0) : v1;
}

void CapturePlot::rebuild()
{
    m_plot->setTimeRange(m_fromS, m_toS);
    const int columns = std::max(1, int(m_plot->plotRect().width()));
    QList<TrendPlot::Series> series;
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (int k = 0; k < m_curves.size(); ++k) {
        const Curve &c = m_curves.at(k);
        TrendPlot::Series s;
        s.id = QString::number(k);
        s.label = c.label;
        s.color = c.color;
        s.axis = TrendPlot::Left;
        s.points = decimate(c.time, c.values, m_fromS, m_toS, columns);
        for (const QPointF &p : std::as_const(s.points)) {
            if (std::isnan(p.y()) || p.x() < m_fromS || p.x() > m_toS)
                continue;
            lo = std::min(lo, p.y());
            hi = std::max(hi, p.y());
        }
        series.append(s);
    }
    if (!(hi >= lo)) {
        lo = 0.0;
        hi = 1.0;
    }
    if (hi - lo < 1e-9) {
        lo -= 0.5;
        hi += 0.5;
    }
    const double pad = (hi - lo) * 0.05;
    TrendPlot::ValueAxis axis;
    axis.used = true;
    axis.min = lo - pad;
    axis.max = hi + pad;
    axis.title = m_valueTitle;
    m_plot->setValueAxis(TrendPlot::Left, axis);
    m_plot->setValueAxis(TrendPlot::Right, TrendPlot::ValueAxis{});
    m_plot->setSeries(series);
}

void CapturePlot::setMarker(int which, std::optional<double> timeS)
{
    if (which < 0 || which > 1)
        return;
    m_markers[static_cast<size_t>(which)] = timeS;
    m_plot->setMarker(which, timeS);
    updateReadout();
}

QString CapturePlot::markerReadout() const
{
    return m_readout->text();
}

void CapturePlot::updateReadout()
{
    const auto &a = m_markers[0];
    const auto &b = m_markers[1];
    if (!a && !b) {
        m_readout->setText(tr("Click the plot to place cursor A, Shift + click for cursor B."));
        return;
    }
    QStringList parts;
    auto ms = [](double s) { return tr("%1 ms").arg(s * 1000.0, 0, 'f', 1); };
    if (a)
        parts << tr("A: %1").arg(ms(*a));
    if (b)
        parts << tr("B: %1").arg(ms(*b));
    if (a && b)
        parts << tr("Δt: %1").arg(ms(*b - *a));
    QStringList lines{parts.join(QStringLiteral("   "))};
    for (const Curve &c : std::as_const(m_curves)) {
        const auto va = a ? valueAt(c.time, c.values, *a) : std::nullopt;
        const auto vb = b ? valueAt(c.time, c.values, *b) : std::nullopt;
        auto text = [](std::optional<double> v) { return v ? QString::number(*v, 'g', 5) : QStringLiteral("–"); };
        QString line = c.label + QStringLiteral(": ");
        if (a)
            line += tr("A %1").arg(text(va));
        if (b)
            line += QStringLiteral("  ") + tr("B %1").arg(text(vb));
        const double delta = vb.value_or(std::nan("")) - va.value_or(std::nan(""));
        if (!std::isnan(delta))
            line += QStringLiteral("  ") + tr("Δvalue %1").arg(QString::number(delta, 'g', 5));
        lines << line;
    }
    m_readout->setText(lines.join(QLatin1Char('\n')));
}

void CapturePlot::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    rebuild();
}

void CapturePlot::changeEvent(QEvent *event)
{
    if (event)
        QWidget::changeEvent(event);
    if (!event || event->type() == QEvent::LanguageChange) {
        m_plot->setTimeTitle(tr("Time from the trigger (s)"));
        updateReadout();
    }
}

} // namespace dd
