#pragma once

#include "ui/workspace/drivepanel.h"

#include <QTimer>

class QLabel;

namespace dd {

class TrendRecorder;
class TrendView;

// The "Trend" tab: records the drive's live channels (Drive::readChannels through the hub)
// into a TrendRecorder shown by a TrendView.
//
// Recording: starts the first time the tab is shown (or with "Record") and, once started,
// keeps sampling whatever tab or drive is shown until the user stops it ("Stop
// recording") or the drive's connection closes: the panel lives as long as its drive's
// tabs, so the recording needs no owner above it. It reads only the channels shown in the
// plot, at the view's sample rate, one request at a time (a slow link lowers the
// effective rate instead of queueing requests; other panels' requests interleave). The
// default rate is what the drive's link can carry (LinkRate). A failed read (link lost,
// drive silent) or a stop marks a gap in the recording (TrendRecorder::appendGap), drawn
// and exported as a gap; the failure is reported once per outage.
// Speed, torque and current are shown at first.
class TrendPanel : public DrivePanel
{
    Q_OBJECT
public:
    // When the link's rate is not known (no connection settings).
    static constexpr double FallbackRateHz = 10.0;

    explicit TrendPanel(const DriveContext &context, QWidget *parent = nullptr);
    ~TrendPanel() override;

    QString panelId() const override { return QStringLiteral("trend"); }
    QString title() const override;

    TrendRecorder *recorder() const { return m_recorder; }
    TrendView *view() const { return m_view; }
    bool isRecording() const { return m_recording; }
    void setRecording(bool recording);
    // The rate the recording starts with: what the drive's link carries for the channels
    // shown (Drive::channelReadUs(), rounded down to two significant digits, at most
    // 1000 Hz), known after the first reading; FallbackRateHz until then. The user's
    // choice in the rate box wins.
    double defaultRateHz() const { return m_defaultRateHz; }
    static double rateForReadUs(double readUs);

protected:
    void activeChanged(bool active) override;
    void driveInfoChanged(const DriveInfo &info) override;
    void retranslate() override;

private:
    void sample();
    void setRate(double hz);
    void updateState();
    void updateDriveTitle();
    void markGap();
    void refreshChannelNames();
    QStringList channelsToRead() const;

    TrendRecorder *m_recorder = nullptr;
    TrendView *m_view = nullptr;
    QLabel *m_unavailable = nullptr;
    QTimer m_timer;
    double m_defaultRateHz = FallbackRateHz;
    bool m_recording = false;
    bool m_rateKnown = false; // the link's rate was asked for
    bool m_userRate = false;  // the user chose a rate
    bool m_started = false;   // recording was started once (the first show starts it)
    bool m_inFlight = false;
    bool m_failing = false;
    bool m_channelsSet = false;
    quint64 m_run = 0; // recording run: replies of an earlier run are dropped
};

} // namespace dd
