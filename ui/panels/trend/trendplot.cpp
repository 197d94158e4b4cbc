#include "ui/panels/trend/trendplot.h"

#include "core/trend/trendaxisscale.h"

#include <QEvent>
#include <QKeyEvent>
#include <QLocale>
#include <QMouseEvent>
#include <QPainter>
#include <QPolygonF>
#include <QWheelEvent>
#include <cmath>

namespace dd {

namespace {

constexpr double Pad = 6.0;
constexpr double TickLength = 4.0;
constexpr double SwatchWidth = 18.0;
constexpr double LegendGap = 14.0;
constexpr double MinPlotWidth = 40.0;
constexpr double MinPlotHeight = 30.0;

const QColor GridColor(0xe4, 0xe4, 0xe4);
const QColor AxisColor(0x60, 0x60, 0x60);
const QColor MarkerColor(0x20, 0x20, 0x20);

} // namespace

TrendPlot::TrendPlot(QWidget *parent)
    : QWidget(parent)
{
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true);
    setMinimumSize(220, 140);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void TrendPlot::setTimeRange(double minS, double maxS)
{
    if (!(maxS > minS))
        maxS = minS + 1e-6;
    m_tMin = minS;
    m_tMax = maxS;
    update();
}

void TrendPlot::setTimeTitle(const QString &title)
{
    m_timeTitle = title;
    update();
}

void TrendPlot::setValueAxis(int axis, const ValueAxis &a)
{
    ValueAxis v = a;
    if (!(v.max > v.min))
        v.max = v.min + 1.0;
    m_axes[static_cast<size_t>(axis)] = v;
    update();
}

void TrendPlot::setSeries(const QList<Series> &series)
{
    m_series = series;
    update();
}

const TrendPlot::Series *TrendPlot::seriesById(const QString &id) const
{
    for (const Series &s : m_series)
        if (s.id == id)
            return &s;
    return nullptr;
}

void TrendPlot::setMarker(int which, std::optional<double> timeS)
{
    m_markers[static_cast<size_t>(which)] = timeS;
    update();
}

void TrendPlot::setHoverTime(std::optional<double> timeS)
{
    m_hover = timeS;
    update();
}

double TrendPlot::timeAtX(double x) const
{
    const QRectF p = plotRect();
    return m_tMin + (x - p.left()) / p.width() * (m_tMax - m_tMin);
}

double TrendPlot::xAtTime(double t) const
{
    const QRectF p = plotRect();
    return p.left() + (t - m_tMin) / (m_tMax - m_tMin) * p.width();
}

double TrendPlot::valueAtY(int axis, double y) const
{
    const QRectF p = plotRect();
    const ValueAxis &a = valueAxis(axis);
    return a.min + (p.bottom() - y) / p.height() * (a.max - a.min);
}

QList<double> TrendPlot::niceTicks(double min, double max, int maxCount, double *step)
{
    QList<double> out;
    const double s = TrendAxisScale::niceStep((max - min) / std::max(1, maxCount));
    if (step)
        *step = s;
    if (!(max > min) || !std::isfinite(min) || !std::isfinite(max))
        return out;
    // Integer multiples of the step, so labels are exact ("0.3", never "0.30000000000000004").
    for (double k = std::ceil(min / s - 1e-9); k * s <= max + s * 1e-9 && out.size() < 1000; k += 1.0)
        out.append(k * s);
    return out;
}

QString TrendPlot::tickLabel(double value, double step)
{
    const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
    if (std::fabs(value) < step * 1e-6)
        value = 0.0; // no "-0"
    return QLocale().toString(value, 'f', std::clamp(decimals, 0, 12));
}

QList<double> TrendPlot::ticks(int axis) const
{
    const Layout l = layoutFor(QRectF(rect()));
    const int lineHeight = fontMetrics().height();
    if (axis < 0)
        return niceTicks(m_tMin, m_tMax, std::max(2, int(l.plot.width() / 90)), nullptr);
    const ValueAxis &a = valueAxis(axis);
    return niceTicks(a.min, a.max, std::max(2, int(l.plot.height() / (lineHeight * 2.2))), nullptr);
}

TrendPlot::Layout TrendPlot::layoutFor(const QRectF &target) const
{
    Layout l;
    l.target = target;
    const QFontMetricsF fm(font());
    const double lh = fm.height();

    // Value axis margins: the widest tick label + the rotated title.
    std::array<double, 2> margin{Pad, Pad};
    const double plotHeightGuess = std::max(MinPlotHeight, target.height() - 4 * lh);
    for (int a = 0; a < 2; ++a) {
        const ValueAxis &ax = m_axes[static_cast<size_t>(a)];
        if (!ax.used)
            continue;
        double step = 1.0;
        const QList<double> t = niceTicks(ax.min, ax.max, std::max(2, int(plotHeightGuess / (lh * 2.2))), &step);
        double w = 0.0;
        for (double v : t)
            w = std::max(w, fm.horizontalAdvance(tickLabel(v, step)));
        margin[static_cast<size_t>(a)] = Pad + lh + Pad + w + TickLength + 2;
    }
    const double left = target.left() + margin[0];
    const double right = target.right() - margin[1];
    const double plotWidth = std::max(MinPlotWidth, right - left);

    // Legend: entries flow left to right and wrap; an entry wider than a line is elided.
    double x = 0.0;
    double y = 0.0;
    const double lineWidth = target.width() - 2 * Pad;
    for (const Series &s : m_series) {
        const QString full = s.label;
        QString text = full;
        double w = SwatchWidth + 4 + fm.horizontalAdvance(text);
        if (w > lineWidth) {
            text = fm.elidedText(full, Qt::ElideMiddle, lineWidth - SwatchWidth - 4);
            w = SwatchWidth + 4 + fm.horizontalAdvance(text);
        }
        if (x > 0 && x + w > lineWidth) {
            x = 0;
            y += lh;
        }
        l.legendTexts.append(text);
        l.legendRects.append(QRectF(target.left() + Pad + x, target.top() + Pad + y, w, lh));
        x += w + LegendGap;
    }
    const double legendHeight = m_series.isEmpty() ? 0.0 : y + lh;
    l.legend = QRectF(target.left() + Pad, target.top() + Pad, lineWidth, legendHeight);

    const double top = target.top() + Pad + legendHeight + Pad + (m_axes[0].used || m_axes[1].used ? lh / 2 : 0);
    const double bottom = target.bottom() - (Pad + lh + Pad + lh + TickLength);
    l.plot = QRectF(left, top, plotWidth, std::max(MinPlotHeight, bottom - top));
    return l;
}

void TrendPlot::render(QPainter *painter, const QRectF &target) const
{
    painter->save();
    painter->setFont(font());
    painter->fillRect(target, Qt::white);
    const Layout l = layoutFor(target);
    paintGreyed(painter, l);
    paintAxes(painter, l);
    paintSeries(painter, l);
    paintMarkers(painter, l);
    paintLegend(painter, l);
    painter->restore();
}

void TrendPlot::setGreyedFrom(std::optional<double> fromS)
{
    m_greyedFrom = fromS;
    update();
}

void TrendPlot::paintGreyed(QPainter *p, const Layout &l) const
{
    if (!m_greyedFrom || *m_greyedFrom >= m_tMax)
        return;
    const QRectF &r = l.plot;
    const double from = std::max(*m_greyedFrom, m_tMin);
    const double x = r.left() + (from - m_tMin) / (m_tMax - m_tMin) * r.width();
    p->fillRect(QRectF(QPointF(x, r.top()), r.bottomRight()), QColor(0xd8, 0xd8, 0xd8));
}

void TrendPlot::paintAxes(QPainter *p, const Layout &l) const
{
    const QFontMetricsF fm(font());
    const double lh = fm.height();
    const QRectF &r = l.plot;
    p->setRenderHint(QPainter::Antialiasing, false);

    // Time axis.
    double step = 1.0;
    const QList<double> tTicks = niceTicks(m_tMin, m_tMax, std::max(2, int(r.width() / 90)), &step);
    for (double t : tTicks) {
        const double x = r.left() + (t - m_tMin) / (m_tMax - m_tMin) * r.width();
        p->setPen(GridColor);
        p->drawLine(QPointF(x, r.top()), QPointF(x, r.bottom()));
        p->setPen(AxisColor);
        p->drawLine(QPointF(x, r.bottom()), QPointF(x, r.bottom() + TickLength));
        const QString label = tickLabel(t, step);
        const double w = fm.horizontalAdvance(label);
        p->drawText(QRectF(x - w / 2 - 2, r.bottom() + TickLength, w + 4, lh), Qt::AlignCenter, label);
    }
    p->setPen(AxisColor);
    p->drawText(QRectF(r.left(), r.bottom() + TickLength + lh, r.width(), lh + Pad), Qt::AlignCenter, m_timeTitle);

    // Value axes: the left one draws the grid; each draws its ticks, labels and title in
    // the colour of its single series (or neutral when it holds several).
    for (int a = 0; a < 2; ++a) {
        const ValueAxis &ax = m_axes[static_cast<size_t>(a)];
        if (!ax.used)
            continue;
        QColor colour = AxisColor;
        int onAxis = 0;
        for (const Series &s : m_series)
            if (s.axis == a) {
                ++onAxis;
                colour = s.color;
            }
        if (onAxis != 1)
            colour = AxisColor;
        double vStep = 1.0;
        const QList<double> vTicks = niceTicks(ax.min, ax.max, std::max(2, int(r.height() / (lh * 2.2))), &vStep);
        const bool left = a == Left;
        const bool grid = left || !m_axes[0].used;
        for (double v : vTicks) {
            const double y = r.bottom() - (v - ax.min) / (ax.max - ax.min) * r.height();
            if (grid) {
                p->setPen(GridColor);
                p->drawLine(QPointF(r.left(), y), QPointF(r.right(), y));
            }
            p->setPen(colour);
            const double x0 = left ? r.left() : r.right();
            p->drawLine(QPointF(x0, y), QPointF(left ? x0 - TickLength : x0 + TickLength, y));
            const QString label = tickLabel(v, vStep);
            if (left)
                p->drawText(QRectF(l.target.left(), y - lh / 2, x0 - TickLength - 2 - l.target.left(), lh),
                            Qt::AlignRight | Qt::AlignVCenter, label);
            else
                p->drawText(QRectF(x0 + TickLength + 2, y - lh / 2, 1000, lh), Qt::AlignLeft | Qt::AlignVCenter, label);
        }
        p->setPen(colour);
        p->drawLine(QPointF(left ? r.left() : r.right(), r.top()), QPointF(left ? r.left() : r.right(), r.bottom()));
        // The title, rotated, along the outer edge.
        p->save();
        if (left) {
            p->translate(l.target.left() + Pad, r.center().y());
            p->rotate(-90);
        } else {
            p->translate(l.target.right() - Pad, r.center().y());
            p->rotate(90);
        }
        const QString title = fm.elidedText(ax.title, Qt::ElideMiddle, r.height());
        p->drawText(QRectF(-r.height() / 2, 0, r.height(), lh), Qt::AlignCenter, title);
        p->restore();
    }
    p->setPen(AxisColor);
    p->drawLine(r.bottomLeft(), r.bottomRight());
}

void TrendPlot::paintSeries(QPainter *p, const Layout &l) const
{
    const QRectF &r = l.plot;
    p->save();
    p->setClipRect(r.adjusted(0, -1, 1, 1));
    p->setRenderHint(QPainter::Antialiasing, false);
    const double sx = r.width() / (m_tMax - m_tMin);
    QPolygonF line;
    for (const Series &s : m_series) {
        const ValueAxis &ax = m_axes[static_cast<size_t>(s.axis)];
        const double sy = r.height() / (ax.max - ax.min);
        // A 1 px cosmetic pen: the raster engine's fast path (wider pens stroke each
        // segment as a polygon, 10x slower for a dense min/max line).
        QPen pen(s.color, 1);
        pen.setCosmetic(true);
        p->setPen(pen);
        line.clear();
        line.reserve(s.points.size());
        const auto flush = [&] {
            if (line.size() > 1)
                p->drawPolyline(line);
            else if (line.size() == 1)
                p->drawPoint(line.first());
            line.clear();
        };
        for (const QPointF &pt : s.points) {
            if (std::isnan(pt.y())) {
                flush(); // a gap: no line across it
                continue;
            }
            // Clamp far-off values so the rasterizer never sees huge coordinates.
            const double y = std::clamp(r.bottom() - (pt.y() - ax.min) * sy, r.top() - 1e4, r.bottom() + 1e4);
            line.append(QPointF(r.left() + (pt.x() - m_tMin) * sx, y));
        }
        flush();
    }
    p->restore();
}

void TrendPlot::paintMarkers(QPainter *p, const Layout &l) const
{
    const QRectF &r = l.plot;
    const QFontMetricsF fm(font());
    const auto xOf = [&](double t) { return r.left() + (t - m_tMin) / (m_tMax - m_tMin) * r.width(); };
    if (m_hover && *m_hover >= m_tMin && *m_hover <= m_tMax) {
        p->setPen(QPen(QColor(0x70, 0x70, 0x70), 1, Qt::DashLine));
        p->drawLine(QPointF(xOf(*m_hover), r.top()), QPointF(xOf(*m_hover), r.bottom()));
    }
    for (int m = 0; m < 2; ++m) {
        const auto &t = m_markers[static_cast<size_t>(m)];
        if (!t || *t < m_tMin || *t > m_tMax)
            continue;
        const double x = xOf(*t);
        p->setPen(QPen(MarkerColor, 1, m == MarkerA ? Qt::SolidLine : Qt::DashDotLine));
        p->drawLine(QPointF(x, r.top()), QPointF(x, r.bottom()));
        const QString name = m == MarkerA ? QStringLiteral("A") : QStringLiteral("B");
        const QRectF box(x + 2, r.top() + 1, fm.horizontalAdvance(name) + 6, fm.height());
        p->fillRect(box, QColor(255, 255, 255, 220));
        p->drawText(box, Qt::AlignCenter, name);
    }
    if (m_banding) {
        p->setPen(QPen(QColor(0x30, 0x60, 0xc0), 1));
        p->setBrush(QColor(0x30, 0x60, 0xc0, 40));
        p->drawRect(m_band);
        p->setBrush(Qt::NoBrush);
    }
}

void TrendPlot::paintLegend(QPainter *p, const Layout &l) const
{
    const QFontMetricsF fm(font());
    for (int i = 0; i < m_series.size() && i < l.legendRects.size(); ++i) {
        const QRectF box = l.legendRects.at(i);
        QPen pen(m_series.at(i).color, 3);
        p->setPen(pen);
        const double y = box.center().y();
        p->drawLine(QPointF(box.left() + 1, y), QPointF(box.left() + SwatchWidth - 2, y));
        p->setPen(palette().color(QPalette::Active, QPalette::Text));
        p->drawText(QRectF(box.left() + SwatchWidth + 4, box.top(), box.width() - SwatchWidth - 4, fm.height()),
                    Qt::AlignLeft | Qt::AlignVCenter, l.legendTexts.at(i));
    }
}

void TrendPlot::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    render(&p, QRectF(rect()));
    if (hasFocus()) {
        p.setPen(QPen(palette().color(QPalette::Highlight), 1, Qt::DotLine));
        p.drawRect(QRectF(rect()).adjusted(0.5, 0.5, -0.5, -0.5));
    }
}

void TrendPlot::mousePressEvent(QMouseEvent *event)
{
    m_pressPos = event->position();
    m_pressButton = event->button();
    m_panLastX = event->position().x();
    m_banding = false;
    event->accept();
}

void TrendPlot::mouseMoveEvent(QMouseEvent *event)
{
    const QPointF pos = event->position();
    const QRectF r = plotRect();
    if (m_pressPos && m_pressButton == Qt::MiddleButton) {
        const double dx = pos.x() - m_panLastX;
        m_panLastX = pos.x();
        if (dx != 0.0)
            emit panBy(-dx / r.width());
    } else if (m_pressPos && m_pressButton == Qt::LeftButton) {
        if (!m_banding && (pos - *m_pressPos).manhattanLength() > 4)
            m_banding = true;
        if (m_banding) {
            m_band = QRectF(*m_pressPos, pos).normalized().intersected(r);
            update();
        }
    }
    if (r.contains(pos))
        emit hoverMoved(timeAtX(pos.x()));
    else
        emit hoverLeft();
}

void TrendPlot::mouseReleaseEvent(QMouseEvent *event)
{
    const QPointF pos = event->position();
    const QRectF r = plotRect();
    const bool wasBanding = m_banding;
    const Qt::MouseButton button = m_pressButton;
    m_banding = false;
    m_pressPos.reset();
    m_pressButton = Qt::NoButton;
    update();
    if (wasBanding) {
        if (m_band.width() > 4 && m_band.height() > 4)
            emit zoomToRect(m_band);
        return;
    }
    if (!r.contains(pos))
        return;
    if (button == Qt::RightButton || (button == Qt::LeftButton && (event->modifiers() & Qt::ShiftModifier)))
        emit markerPlaced(MarkerB, timeAtX(pos.x()));
    else if (button == Qt::LeftButton)
        emit markerPlaced(MarkerA, timeAtX(pos.x()));
}

void TrendPlot::mouseDoubleClickEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton)
        emit resetRequested();
}

void TrendPlot::wheelEvent(QWheelEvent *event)
{
    const int dy = event->angleDelta().y() != 0 ? event->angleDelta().y() : event->angleDelta().x();
    if (dy == 0)
        return;
    if (event->modifiers() & Qt::ShiftModifier)
        emit panBy(dy > 0 ? -0.1 : 0.1);
    else
        emit zoomBy(dy > 0 ? 0.8 : 1.25, std::clamp(timeAtX(event->position().x()), m_tMin, m_tMax));
    event->accept();
}

void TrendPlot::keyPressEvent(QKeyEvent *event)
{
    const double centre = (m_tMin + m_tMax) / 2;
    switch (event->key()) {
    case Qt::Key_Plus:
    case Qt::Key_Equal: emit zoomBy(0.8, centre); break;
    case Qt::Key_Minus: emit zoomBy(1.25, centre); break;
    case Qt::Key_Left: emit panBy(-0.1); break;
    case Qt::Key_Right: emit panBy(0.1); break;
    case Qt::Key_Home:
    case Qt::Key_0: emit resetRequested(); break;
    // Esc is STOP everywhere in the application (ui/shell/stopaction.h): never taken here.
    case Qt::Key_Delete:
    case Qt::Key_Backspace: emit markersCleared(); break;
    default: QWidget::keyPressEvent(event); return;
    }
    event->accept();
}

void TrendPlot::leaveEvent(QEvent *event)
{
    emit hoverLeft();
    QWidget::leaveEvent(event);
}

void TrendPlot::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::FontChange || event->type() == QEvent::PaletteChange)
        update();
    QWidget::changeEvent(event);
}

} // namespace dd
