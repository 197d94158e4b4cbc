#pragma once

#include "core/common/error.h"
#include "core/trend/trendchannel.h"

#include <QHash>
#include <QPoint>
#include <QPointF>
#include <QTimer>
#include <QWidget>
#include <optional>

class QChart;
class QChartView;
class QGraphicsLineItem;
class QLabel;
class QLineSeries;
class QValueAxis;

namespace dd {

class TrendChannelPanel;
class TrendControls;
class TrendRecorder;

// Live trend plot of a TrendRecorder (which it does not own and never feeds: the owner's
// sampler appends to the recorder).
//
// - One QLineSeries per channel on a shared value axis; each channel has a scale and an
//   offset (TrendChannelPanel) so channels of different magnitude fit together. The time
//   axis is in seconds since the recording's origin.
// - A refresh timer (25 Hz, only while shown; slower, down to 5 Hz, if a refresh takes
//   over 10 ms) min/max-decimates the visible window to the plot width (TrendPlotBuilder)
//   and calls QXYSeries::replace() once per series: at most two points per pixel column.
//   A frozen (paused or zoomed) view is redrawn only when its window, size or settings
//   change.
// - Window 10 s … 10 min; following the newest sample unless paused. Pause freezes the
//   view while the recorder keeps recording; resume jumps back to live and drops zoom.
// - Zoom: drag a rectangle (right click zooms out); zooming pauses following. "Reset zoom"
//   shows the selected window again.
// - Cursor: a vertical line under the mouse and a readout of every shown channel's real
//   value (the sample nearest in time).
// - Export: CSV of the shown channels (whole recording or the visible window, real values,
//   CsvWriter format) and PNG of the plot.
// - The sample-rate box only emits sampleRateChanged(); the owner applies it.
// No OpenGL (it crashes under the offscreen platform and buys nothing at ≤ 2 points/px).
class TrendView : public QWidget
{
    Q_OBJECT
public:
    enum class ExportRange { WholeRecording, VisibleWindow };

    explicit TrendView(TrendRecorder *recorder, QWidget *parent = nullptr);
    ~TrendView() override;

    TrendRecorder *recorder() const { return m_recorder; }

    int windowSeconds() const;          // one of TrendControls::windowChoicesSeconds()
    void setWindowSeconds(int seconds); // the nearest choice

    double sampleRate() const;
    void setSampleRate(double hz); // shows the rate the owner uses; emits nothing

    bool isChannelVisible(const QString &id) const;
    void setChannelVisible(const QString &id, bool visible);
    void setChannelScale(const QString &id, double scale, double offset = 0.0);

    bool isZoomed() const { return m_zoomed; }
    void resetZoom();

    // The time window drawn by the last refresh, in recorder time (µs).
    qint64 visibleFromUs() const { return m_viewFromUs; }
    qint64 visibleToUs() const { return m_viewToUs; }
    // Decimate and redraw now if anything changed (the timer calls this).
    void refreshNow();

    Error exportCsv(const QString &path, ExportRange range) const;
    Error exportPng(const QString &path) const;

    // Cursor at a position of chartView()->viewport(); hidden outside the plot area.
    void setCursorPosition(const QPoint &viewportPos);
    void hideCursor();
    QString cursorReadout() const;

    TrendControls *controls() const { return m_controls; }
    TrendChannelPanel *channelPanel() const { return m_panel; }
    QChart *chart() const { return m_chart; }
    QChartView *chartView() const { return m_chartView; }
    QLineSeries *series(const QString &id) const { return m_series.value(id); }

signals:
    void sampleRateChanged(double hz);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    // The point lists of a refresh, one per visible series.
    using SeriesPoints = QList<std::pair<QLineSeries *, QList<QPointF>>>;

    void buildUi();
    void buildChart();
    void buildControls();
    void buildChannelPanel();
    void retranslateUi();
    void onWindowChanged();
    void rebuildSeries();
    void updateSeriesName(const QString &id);
    void computeWindow(qint64 *fromUs, qint64 *toUs) const;
    // Whether the last refresh drew this window at this width with nothing changed since.
    bool isDrawn(qint64 fromUs, qint64 toUs, int width) const;
    // The decimated points of the visible channels (hidden ones are emptied) and their
    // value range (widened into *yMin, *yMax).
    SeriesPoints decimate(qint64 fromUs, qint64 toUs, int width, double *yMin, double *yMax);
    // Sets the axes to the window and the value range; empties the series first if an axis
    // moves.
    void moveAxes(qint64 fromUs, qint64 toUs, double yMin, double yMax, const SeriesPoints &updates);
    int plotWidthPx() const;
    void onAxisRangeChanged();
    void dropZoom();
    void onPausedChanged(bool paused);
    void updateCursor();
    void updateStatus();
    void invalidate() { ++m_stateVersion; }
    QStringList exportChannelIds() const;
    QString askSavePath(const QString &title, const QString &suffix, const QString &filter);
    void exportCsvInteractive(ExportRange range);
    void exportPngInteractive();
    std::optional<double> timeAtViewportX(int x) const;

    TrendRecorder *m_recorder;
    QList<TrendChannel> m_channels;
    QHash<QString, QLineSeries *> m_series;
    QHash<QString, QColor> m_colors;

    QChart *m_chart = nullptr;
    QChartView *m_chartView = nullptr;
    QValueAxis *m_axisX = nullptr;
    QValueAxis *m_axisY = nullptr;
    QGraphicsLineItem *m_cursorLine = nullptr;
    TrendChannelPanel *m_panel = nullptr;
    TrendControls *m_controls = nullptr;
    QWidget *m_panelScroll = nullptr;
    QLabel *m_readout = nullptr;
    QLabel *m_status = nullptr;
    QTimer m_timer;

    // View state.
    bool m_zoomed = false;
    qint64 m_zoomFromUs = 0;
    qint64 m_zoomToUs = 0;
    bool m_zoomY = false;
    double m_zoomYMin = 0.0;
    double m_zoomYMax = 1.0;
    int m_updatingAxes = 0;
    bool m_handlingZoom = false;
    qint64 m_viewFromUs = 0;
    qint64 m_viewToUs = 0;
    std::optional<QPoint> m_cursorPos;

    // What the last refresh drew, to skip refreshes that would change nothing.
    quint64 m_stateVersion = 0;
    bool m_drawn = false;
    quint64 m_drawnRevision = 0;
    quint64 m_drawnState = 0;
    qint64 m_drawnFrom = 0;
    qint64 m_drawnTo = 0;
    int m_drawnWidth = 0;
};

} // namespace dd
