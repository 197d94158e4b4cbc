#pragma once

#include "cli/clicommand.h"
#include "core/drive/drivetypes.h"
#include "core/drive/motiongoal.h"

#include <QElapsedTimer>
#include <QTimer>

#include <optional>

// Commands that move the axis: jog, move, home. Ctrl-C / SIGTERM stop the axis.

namespace dd {

// jog SPEED [--duration S]: runs, renews the drive's jog lease, stops when the duration
// ends, on SIGINT/SIGTERM and on any error. A second signal sends an emergency stop.
class JogCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit JogCommand(CliContext *c);
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;
    void interrupt(int signalNumber) override;
    void linkLost(const Error &why) override;

private:
    enum class Reason { Duration, Signal, Error };
    void stopNow(Reason reason, const Error &error = {});
    void onStopped(DriveReply *reply);

    qint32 m_speed = 0;
    double m_durationS = 0; // 0: until a signal
    QTimer m_renew;
    QTimer m_duration;
    QElapsedTimer m_clock;
    bool m_stopping = false;
    bool m_emergencySent = false;
    bool m_enable = false; // --enable: the motion may switch the power stage on
    Reason m_reason = Reason::Duration;
    Error m_error;
    std::optional<JogEnd> m_end; // what stops the axis, once the drive has said
};

// A motion that runs to its end: move and home. After the command is accepted it waits
// (polling the drive's state) until the axis is at rest again, keeping the link and its
// keep-alives up; --no-wait returns at once. Ctrl-C / SIGTERM stop the axis.
class PositioningCommand : public CliCommand
{
    Q_OBJECT
public:
    PositioningCommand(const QString &name, CliContext *c);
    void interrupt(int signalNumber) override;

protected:
    bool prepareWait(const CliInvocation &inv);
    // Starts the motion's reply handling; `json` / `text` describe it. With --wait, the
    // motion succeeds only if the axis comes to rest where `goal` says (MotionGoal: a move at
    // its target within the in-position window, a homing with the origin found); at rest
    // elsewhere it fails (Cancelled, exit 1) and says where it stopped.
    void follow(DriveReply *reply, const QJsonObject &json, const QString &text, const MotionGoal &goal);

private:
    void poll();
    void finishAtRest(const DriveStatus &s);

    bool m_wait = true;
    bool m_stopping = false;
    bool m_sawRunning = false;
    int m_idlePolls = 0;
    QTimer m_poll;
    QElapsedTimer m_clock;
    QJsonObject m_json;
    QString m_text;
    MotionGoal m_goal;
};

// move (--by N | --to N) [--speed V] [--no-wait]
class MoveCommand : public PositioningCommand
{
    Q_OBJECT
public:
    explicit MoveCommand(CliContext *c)
        : PositioningCommand(QStringLiteral("move"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;

private:
    bool m_relative = true;
    qint64 m_target = 0;
    qint32 m_speed = 0;
    bool m_enable = false; // --enable: the motion may switch the power stage on
};

// home [--positive] [--no-wait]
class HomeCommand : public PositioningCommand
{
    Q_OBJECT
public:
    explicit HomeCommand(CliContext *c)
        : PositioningCommand(QStringLiteral("home"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;

private:
    bool m_positive = false;
};

} // namespace dd
