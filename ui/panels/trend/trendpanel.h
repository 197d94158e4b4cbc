#pragma once

#include "ui/workspace/drivepanel.h"

#include <QElapsedTimer>
#include <QTimer>

class QLabel;
class QScrollArea;

namespace dd {

class TrendRecorder;
class TrendView;

// The "Trend" tab: samples the drive's live channels (Drive::readChannels through the hub)
// into a TrendRecorder shown by a TrendView. Samples only while the tab is showing (the
// link is shared by every drive on it), at the view's sample rate, one request at a time
// (a slow link lowers the effective rate instead of queueing requests), and only the
// channels shown in the plot. Speed, torque and current are shown at first.
class TrendPanel : public DrivePanel
{
    Q_OBJECT
public:
    static constexpr double DefaultRateHz = 10.0;

    explicit TrendPanel(const DriveContext &context, QWidget *parent = nullptr);
    ~TrendPanel() override;

    QString panelId() const override { return QStringLiteral("trend"); }
    QString title() const override;

    TrendRecorder *recorder() const { return m_recorder; }
    TrendView *view() const { return m_view; }

protected:
    void activeChanged(bool active) override;
    void driveInfoChanged(const DriveInfo &info) override;
    void retranslate() override;

private:
    void sample();
    void setRate(double hz);
    void updateState();
    QStringList channelsToRead() const;

    TrendRecorder *m_recorder = nullptr;
    TrendView *m_view = nullptr;
    QLabel *m_unavailable = nullptr;
    QScrollArea *m_scroll = nullptr;
    QTimer m_timer;
    QElapsedTimer m_clock; // sample time when the drive gives none
    bool m_inFlight = false;
    bool m_failing = false;
    bool m_channelsSet = false;
};

} // namespace dd
