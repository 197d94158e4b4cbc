#pragma once

#include <QColor>
#include <QPointF>
#include <QVector>
#include <QWidget>
#include <array>
#include <optional>

class QLabel;

namespace dd {

class TrendPlot;

// The capture plot of the Tuning tab: runs overlaid on one time axis, seconds relative to
// each run's trigger (so overlaid runs are aligned on it), drawn by the trend's TrendPlot
// (its axes, cursors, zoom and pan gestures). Each curve is min/max-decimated to the plot's
// pixel columns before it is handed to the plot, so eight runs of 10 000 samples cost about
// what 8 × 2 × width points do (docs/performance.md, bench_tuningoverlay).
// Cursors A (click) and B (Shift + click or right click): their times, Δt, and each curve's
// value at both and Δvalue, read off the line (interpolated between samples).
class CapturePlot : public QWidget
{
    Q_OBJECT
public:
    struct Curve
    {
        QString label; // legend: the run
        QColor color;
        QVector<double> time;   // s relative to the trigger, non-decreasing
        QVector<double> values; // NaN: not read (a break)
    };

    explicit CapturePlot(QWidget *parent = nullptr);

    // Shows the curves (fits the time and value axes to them unless zoomed).
    void setCurves(const QList<Curve> &curves, const QString &valueTitle);
    const QList<Curve> &curves() const { return m_curves; }
    void resetZoom();
    void setTimeWindow(double fromS, double toS); // zooms the time axis

    void setMarker(int which, std::optional<double> timeS);
    std::optional<double> marker(int which) const { return m_markers[static_cast<size_t>(which)]; }
    QString markerReadout() const;
    TrendPlot *plot() const { return m_plot; }

    // Rebuilds the plot's series for its current width (the decimation); the bench times it.
    void rebuild();
    // Min/max decimation of (time, values) inside [fromS, toS] to `columns` buckets: per
    // bucket the lowest and highest sample in time order, plus the nearest sample outside
    // each end so that the line reaches the edges. NaN breaks the line.
    static QList<QPointF> decimate(const QVector<double> &time, const QVector<double> &values, double fromS, double toS,
                                   int columns);
    // Linear interpolation at t; nullopt outside the samples or next to a NaN.
    static std::optional<double> valueAt(const QVector<double> &time, const QVector<double> &values, double t);

protected:
    void resizeEvent(QResizeEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void fitTime();
    void updateReadout();

    TrendPlot *m_plot = nullptr;
    QLabel *m_readout = nullptr;
    QList<Curve> m_curves;
    QString m_valueTitle;
    double m_fromS = 0.0;
    double m_toS = 1.0;
    bool m_zoomed = false;
    std::array<std::optional<double>, 2> m_markers;
};

} // namespace dd
