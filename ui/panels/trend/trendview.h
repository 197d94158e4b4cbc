#pragma once

#include "core/common/error.h"
#include "core/trend/decimationcache.h"
#include "core/trend/trendchannel.h"

#include <QHash>
#include <QPointF>
#include <QTimer>
#include <QWidget>
#include <array>
#include <optional>

class QLabel;
class QPainter;

namespace dd {

class TrendChannelPanel;
class TrendControls;
class TrendPlot;
class TrendRecorder;

// Live trend plot of a TrendRecorder (which it does not own and never feeds: the owner's
// sampler appends to the recorder).
//
// - The plot (TrendPlot) takes most of the tab; the channels are a compact checkable list
//   beside it (TrendChannelPanel) whose per-channel menu sets the value axis (left or
//   right) and a scale and offset. Each axis fits its own channels; ticks sit on 1-2-5
//   steps. No two shown channels share a colour.
// - A refresh timer (25 Hz, only while shown; slower, down to 5 Hz, if a refresh takes
//   over 10 ms) min/max-decimates the visible window to the plot width (TrendPlotBuilder,
//   buckets anchored to time; each channel's DecimationCache keeps the finished ones, so a
//   live update recomputes only the window's edges) and repaints. A frozen (paused or zoomed) view is redrawn only when its window, size
//   or settings change. Gaps in the recording (TrendRecorder::appendGap) are drawn as
//   gaps, never as a ramp.
// - Window 10 s … 10 min; following the newest sample unless paused. Pause freezes the
//   view while the recorder keeps recording; resume jumps back to live and drops zoom.
// - Zoom and pan (TrendPlot's mouse and keys); zooming pauses following; "Reset zoom",
//   Home or a double click shows the selected window again.
// - Hover readout: every shown channel's value where the pointer is, read off the line
//   (interpolated between the samples either side; "–" in a gap). Cursors A and B (click,
//   Shift + click): their times, Δt and each channel's Δvalue.
// - Export: CSV of the shown channels (whole recording or visible window, real values,
//   CsvWriter format; the view says where it wrote), PNG and SVG of the plot with a title
//   block (drive, date, channels with units and axes).
// - The record button and the sample-rate box only emit; the owner records.
class TrendView : public QWidget
{
    Q_OBJECT
public:
    enum class ExportRange { WholeRecording, VisibleWindow };
    enum class ExportKind { CsvWhole, CsvWindow, Png, Svg };

    explicit TrendView(TrendRecorder *recorder, QWidget *parent = nullptr);
    ~TrendView() override;

    TrendRecorder *recorder() const { return m_recorder; }

    int windowSeconds() const;          // one of TrendControls::windowChoicesSeconds()
    void setWindowSeconds(int seconds); // the nearest choice

    double sampleRate() const;
    void setSampleRate(double hz);     // shows the rate the owner uses; emits nothing
    void setRecording(bool recording); // shows the owner's state; emits nothing

    bool isChannelVisible(const QString &id) const;
    void setChannelVisible(const QString &id, bool visible);
    void setChannelScale(const QString &id, double scale, double offset = 0.0);
    void setChannelAxis(const QString &id, int axis); // TrendPlot::Left / Right
    int channelAxis(const QString &id) const;
    QColor channelColor(const QString &id) const { return m_colors.value(id); }

    bool isZoomed() const { return m_zoomed; }
    void resetZoom();
    // Shows [fromUs, toUs] (recorder time) and stops following; value axes keep fitting.
    void zoomTime(qint64 fromUs, qint64 toUs);
    void zoomAround(double factor, double anchorS); // factor < 1 zooms in
    void pan(double fraction);                      // of the window; > 0: later

    // The time window drawn by the last refresh, in recorder time (µs).
    qint64 visibleFromUs() const { return m_viewFromUs; }
    qint64 visibleToUs() const { return m_viewToUs; }
    // Decimate and redraw now if anything changed (the timer calls this).
    void refreshNow();

    // For the export's title block: which drive ("servo-modbus 1 · ASD-B2 …").
    void setDriveTitle(const QString &title) { m_driveTitle = title; }
    Error exportCsv(const QString &path, ExportRange range) const;
    Error exportPng(const QString &path) const;
    Error exportSvg(const QString &path) const;
    // What the Export menu does once a path is chosen: writes, then says where (message())
    // or why not, and emits fileWritten(path) on success.
    bool exportFile(ExportKind kind, const QString &path);
    // The title block's lines (drive, date, channels with units).
    QStringList titleBlock() const;

    // Hover: the readout of every shown channel at a time (s since the origin).
    void setHoverTime(std::optional<double> timeS);
    QString cursorReadout() const;
    // Cursors A (0) and B (1), s since the origin.
    void setMarker(int which, std::optional<double> timeS);
    std::optional<double> marker(int which) const { return m_markers[static_cast<size_t>(which)]; }
    QString markerReadout() const;
    // The last message (export written, export failed), for the user and the tests.
    QString message() const;

    TrendControls *controls() const { return m_controls; }
    TrendChannelPanel *channelPanel() const { return m_panel; }
    TrendPlot *plot() const { return m_plot; }

signals:
    void sampleRateChanged(double hz);
    void recordToggled(bool recording);
    void fileWritten(const QString &path);

protected:
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void buildUi();
    void connectPlot();
    void retranslateUi();
    void onWindowChanged();
    void onChannelsChanged();
    void assignColors();
    void computeWindow(qint64 *fromUs, qint64 *toUs) const;
    bool isDrawn(qint64 fromUs, qint64 toUs, int width) const;
    QString seriesLabel(const TrendChannel &c) const;
    QString axisTitle(int axis) const;
    void enterZoom(qint64 fromUs, qint64 toUs);
    void zoomToRect(const QRectF &widgetRect);
    void dropZoom();
    void onPausedChanged(bool paused);
    void updateReadouts();
    void updateStatus();
    void showMessage(const QString &text, bool problem);
    void invalidate() { ++m_stateVersion; }
    QStringList exportChannelIds() const;
    void renderExport(QPainter *painter, const QSize &size) const;
    int titleBlockHeight(int width) const;
    QString askSavePath(const QString &title, const QString &suffix, const QString &filter);
    void exportCsvInteractive(ExportRange range);
    void exportImageInteractive(bool svg);
    qint64 usAt(double seconds) const;
    QString valueText(const TrendChannel &c, std::optional<double> v) const;

    TrendRecorder *m_recorder;
    QList<TrendChannel> m_channels;
    QHash<QString, QColor> m_colors;
    QHash<QString, DecimationCache> m_decimation; // per channel: finished buckets of the window
    QString m_driveTitle;

    TrendPlot *m_plot = nullptr;
    TrendChannelPanel *m_panel = nullptr;
    TrendControls *m_controls = nullptr;
    QLabel *m_readout = nullptr;
    QLabel *m_markerReadout = nullptr;
    QLabel *m_message = nullptr;
    QLabel *m_status = nullptr;
    QTimer m_timer;

    // View state.
    bool m_zoomed = false;
    qint64 m_zoomFromUs = 0;
    qint64 m_zoomToUs = 0;
    std::array<std::optional<std::pair<double, double>>, 2> m_zoomY;
    std::array<std::pair<double, double>, 2> m_axisRange{std::make_pair(0.0, 1.0), std::make_pair(0.0, 1.0)};
    bool m_handlingZoom = false;
    qint64 m_viewFromUs = 0;
    qint64 m_viewToUs = 0;
    std::optional<double> m_hover;
    std::array<std::optional<double>, 2> m_markers;

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
