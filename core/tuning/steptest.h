#pragma once

#include "core/common/error.h"
#include "core/drive/drivetypes.h"
#include "core/tuning/capturesettings.h"
#include "core/tuning/commandwatch.h"
#include "core/tuning/steplimits.h"
#include "core/tuning/stepplan.h"
#include "core/tuning/stepresult.h"
#include "core/tuning/stepspec.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <functional>
#include <optional>

namespace dd {

class CaptureSession;
class Drive;
class DriveReply;
struct ChannelInfo;

// A step-response test on a live drive (docs/tuning.md), for the CLI's `step` and the GUI's
// Tuning tab:
//  1. start() checks the spec and the limits, what the drive can do, and the test's travel
//     and time at full speed (StepPlan without the stop); a refusal is returned at once
//     and NOTHING is sent.
//  2. It reads the drive's state (an active alarm refuses the test; the start position) and
//     the tuning parameters (the run's snapshot), predicts the whole test with the stop at
//     the drive's deceleration (StepPlan; refused when it does not fit the limits, no
//     motion sent), arms a capture with the "motion" trigger and, once its pre-trigger
//     window is full, sends the motion and fires the trigger. Velocity and reversal run
//     under the jog lease (renewed here); a position step is a relative move.
//  3. While it runs, an alarm, abort() (STOP), the captured speed above maxSpeed, a
//     stopping point (position + stopping distance at the measured speed) beyond
//     maxTravel, the motion not at rest within maxDurationS, a lost link, an expired lease,
//     a failed capture, or the drive no longer doing what the test asked (CommandWatch:
//     stopped, disabled or commanded by someone else) abort it: the axis is stopped and
//     seen at rest (stopConfirmed), or the result says why not. An aborted test sends no
//     further motion; its capture up to the end is handed in the result (run marked
//     aborted).
//  4. A completed test goes back to the start position (unless the spec says otherwise) —
//     a motion announced by progress(), under the same limits and STOP — computes the
//     metrics (StepMetrics) and hands the run (TuningRun) in the result.
// finished() comes exactly once per started test (not when the object is destroyed
// mid-test: the destructor then sends a stop). Lives in the drive's thread.
class StepTest : public QObject
{
    Q_OBJECT
public:
    enum class Phase { Idle, Preparing, Arming, Moving, Stopping, Returning, Done };
    Q_ENUM(Phase)

    explicit StepTest(Drive *drive, QObject *parent = nullptr);
    ~StepTest() override;

    // The checks start() makes before anything is sent: the spec, the limits, the drive's
    // capabilities and channels. No I/O.
    static Error check(const Drive *drive, const StepSpec &spec, const StepLimits &limits);
    // The channels captured for `kind` on this drive: those of speed, speed-command,
    // position-error, torque, current and position that it offers (position always: it is
    // what the travel limit watches).
    static QStringList channelsFor(const Drive *drive, StepSpec::Kind kind);

    // Starts the test; an error (nothing sent, no finished()) when it is refused.
    Error start(const StepSpec &spec, const StepLimits &limits);
    // STOP: aborts a running test (the axis is stopped, finished() follows). No-op when idle.
    void abort(const QString &reason = QString());
    // The link went away (the drive's connectionLost() does the same): aborts without a
    // stop command; the result says what stops the axis (the drive's watchdog or nothing).
    void linkLost(const Error &why);
    bool isRunning() const { return m_phase != Phase::Idle && m_phase != Phase::Done; }
    Phase phase() const { return m_phase; }
    const StepSpec &spec() const { return m_spec; }
    const StepLimits &limits() const { return m_limits; }
    // The last finished test's result.
    const StepResult &result() const { return m_result; }

    static QString phaseId(Phase phase); // "preparing", "arming", "moving", ...

signals:
    // Where the test is, with a translated line for the user.
    void progress(dd::StepTest::Phase phase, const QString &message);
    // A live sample of the capture (seconds since the capture started; per channel).
    void sampled(double timeS, const QMap<QString, double> &values);
    void finished(const dd::StepResult &result);

private:
    void setPhase(Phase phase, const QString &message);
    void watch(DriveReply *reply, std::function<void(DriveReply *)> handler);
    void readState();
    void readSnapshot();
    void arm();
    void sendMotion();
    void sendOwnStop(std::function<void(DriveReply *)> handler);
    void onStepTimer();
    void onSample(double timeS, const QMap<QString, double> &values);
    bool checkTravel(qint64 position);
    void onCaptured(const CaptureData &capture);
    void waitAtRest();
    void pollAtRest();
    void countRest(const DriveStatus &status);
    void afterRest();
    void buildRun();
    void goBack();
    void pollBack();
    void abortWith(const QString &cause, const Error &error);
    void abortOnAlarm(int code);
    // An "external-stop" that came with an alarm: the alarm was the cause.
    void alarmWasTheCause(int code);
    // The drive no longer does what the test asked (`what`, from CommandWatch).
    void abortExternal(const QString &what);
    // Refused before any motion: outcome Failed, abortCause "refused".
    void refuse(const Error &error);
    void planWithDeceleration();
    void onStatus(const DriveStatus &status);
    void noteDistance(qint64 position);
    void buildAbortedRun();
    // The status a poll read while the test is still in `phase`; aborts (link lost, alarm)
    // and returns nothing otherwise.
    std::optional<DriveStatus> statusWhile(DriveReply *reply, Phase phase);
    void confirmStopped();
    void finish(StepResult::Outcome outcome);

    QPointer<Drive> m_drive;
    StepSpec m_spec;
    StepLimits m_limits;
    CaptureSettings m_settings;
    QStringList m_channels;
    Phase m_phase = Phase::Idle;
    StepResult m_result;
    CaptureSession *m_session = nullptr;
    CaptureData m_capture;
    bool m_haveCapture = false;
    bool m_motionDone = false;    // the motion's commands are done (stop sent / move accepted)
    bool m_restConfirmed = false; // seen at rest after the motion
    bool m_startKnown = false;
    qint64 m_start = 0;
    QList<TuningSnapshotEntry> m_snapshot;
    StepPlan m_plan;
    CommandWatch m_watch;
    // The axis' speed in counts/s, from the captured positions (the stopping distance).
    QList<QPair<double, qint64>> m_recent; // (time, position) of the last few ms
    double m_countsPerS = 0.0;
    double m_lastSampleT = -1.0;
    double m_sampleGap = 0.0; // running mean of the time between samples
    QTimer m_renew;
    QTimer m_step;  // the commanded time (velocity, reversal)
    QTimer m_limit; // maxDurationS from the motion command
    QTimer m_retry; // status polls
    QElapsedTimer m_motionClock;
    double m_triggerAt = 0.0;  // the motion command, on the capture's clock
    double m_reversalAt = 0.0; // reversal: the second command, seconds after the first
    int m_segment = 0;         // reversal: 0 = +speed, 1 = -speed
    bool m_stopSent = false;
    bool m_aborting = false;
    bool m_linkLost = false;
    bool m_ownStop = false; // our own stop() is being sent (not a STOP from elsewhere)
    bool m_emergencySent = false;
    bool m_sawRunning = false;
    QString m_jogEnd;      // the drive's word on how the last jog ended
    int m_atRestPolls = 0; // statuses at rest with the position held
    bool m_havePolledPosition = false;
    qint64 m_polledPosition = 0;
    quint64 m_generation = 0; // replies of an earlier test are ignored
};

} // namespace dd
