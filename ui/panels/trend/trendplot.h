#pragma once

#include <QColor>
#include <QList>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QWidget>
#include <array>
#include <optional>

namespace dd {

// The trend's plot surface, painted with QPainter (no Qt Charts: it cannot break a line at
// a gap, and strokes every series on each change). It draws what TrendView hands it: a
// time axis in seconds, up to two value axes (left and right, each with its own range and
// title), the series (points in axis units; y = NaN breaks the line: a gap), a legend
// that wraps instead of being cut, two measurement cursors (A and B), the hover line and
// the zoom rectangle. Ticks sit on 1-2-5 steps and are labelled with just the decimals the
// step needs.
//
// Input (TrendView acts on the signals; the plot keeps no zoom state):
// - mouse: drag a rectangle to zoom; wheel zooms time around the pointer (Shift + wheel
//   pans); middle-button drag pans; click places cursor A, Shift + click or right click
//   cursor B; double click resets the zoom.
// - keyboard: + / − zoom, ← / → pan, Home (or 0) resets, Esc removes the cursors.
// render() paints the same picture into any device (the PNG / SVG export).
class TrendPlot : public QWidget
{
    Q_OBJECT
public:
    enum Axis { Left = 0, Right = 1 };
    enum Marker { MarkerA = 0, MarkerB = 1 };

    struct Series
    {
        QString id;
        QString label; // legend text
        QColor color;
        int axis = Left;
        QList<QPointF> points; // x: s, y: axis units (NaN: a break)
    };
    struct ValueAxis
    {
        bool used = false;
        double min = 0.0;
        double max = 1.0;
        QString title;
    };

    explicit TrendPlot(QWidget *parent = nullptr);

    void setTimeRange(double minS, double maxS);
    double timeMin() const { return m_tMin; }
    double timeMax() const { return m_tMax; }
    void setTimeTitle(const QString &title);
    QString timeTitle() const { return m_timeTitle; }
    void setValueAxis(int axis, const ValueAxis &a);
    const ValueAxis &valueAxis(int axis) const { return m_axes[static_cast<size_t>(axis)]; }
    void setSeries(const QList<Series> &series);
    const QList<Series> &series() const { return m_series; }
    const Series *seriesById(const QString &id) const;

    // A greyed stretch of the x axis from `fromS` to its right end (the spectrum's band
    // above what it can resolve); nullopt: none.
    void setGreyedFrom(std::optional<double> fromS);
    std::optional<double> greyedFrom() const { return m_greyedFrom; }

    void setMarker(int which, std::optional<double> timeS);
    std::optional<double> marker(int which) const { return m_markers[static_cast<size_t>(which)]; }
    void setHoverTime(std::optional<double> timeS);

    // Geometry within the widget (and within any render() target of that size).
    QRectF plotRect() const { return layoutFor(QRectF(rect())).plot; }
    double timeAtX(double x) const;
    double xAtTime(double t) const;
    double valueAtY(int axis, double y) const;
    // The legend entries as drawn (elided only when one alone is wider than the plot).
    QStringList legendTexts() const { return layoutFor(QRectF(rect())).legendTexts; }
    // The tick values of an axis (time: -1) as drawn at the current size.
    QList<double> ticks(int axis) const;

    void render(QPainter *painter, const QRectF &target) const;

    // 1-2-5 ticks in [min, max] at most maxCount of them; *step gets the step.
    static QList<double> niceTicks(double min, double max, int maxCount, double *step);
    // A tick label: the decimals the step needs, no more ("0.5", "1500", "0.02").
    static QString tickLabel(double value, double step);

signals:
    void hoverMoved(double timeS);
    void hoverLeft();
    void markerPlaced(int which, double timeS);
    void markersCleared();
    void zoomToRect(const QRectF &widgetRect);
    void zoomBy(double factor, double anchorS); // factor < 1: zoom in
    void panBy(double fraction);                // of the time window; > 0: later
    void resetRequested();

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void leaveEvent(QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    struct Layout
    {
        QRectF target;
        QRectF plot;
        QRectF legend;
        QStringList legendTexts;
        QList<QRectF> legendRects; // one per legend text
    };
    Layout layoutFor(const QRectF &target) const;
    void paintAxes(QPainter *p, const Layout &l) const;
    void paintSeries(QPainter *p, const Layout &l) const;
    void paintGreyed(QPainter *p, const Layout &l) const;
    void paintLegend(QPainter *p, const Layout &l) const;
    void paintMarkers(QPainter *p, const Layout &l) const;

    double m_tMin = 0.0;
    double m_tMax = 10.0;
    QString m_timeTitle;
    std::array<ValueAxis, 2> m_axes;
    QList<Series> m_series;
    std::array<std::optional<double>, 2> m_markers;
    std::optional<double> m_hover;
    std::optional<double> m_greyedFrom;
    // Mouse gestures.
    std::optional<QPointF> m_pressPos;
    Qt::MouseButton m_pressButton = Qt::NoButton;
    bool m_banding = false;
    QRectF m_band;
    double m_panLastX = 0.0;
};

} // namespace dd
