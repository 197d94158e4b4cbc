#pragma once

#include "clicommand.h"

#include <QElapsedTimer>
#include <QTimer>

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
    double m_durationS = 0;      // 0: until a signal
    QTimer m_renew;
    QTimer m_duration;
    QElapsedTimer m_clock;
    bool m_stopping = false;
    bool m_emergencySent = false;
    Reason m_reason = Reason::Duration;
    Error m_error;
};

// move (--by N | --to N) [--speed V]
class MoveCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit MoveCommand(CliContext *c) : CliCommand(QStringLiteral("move"), c) {}
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;
    void interrupt(int signalNumber) override;

private:
    bool m_relative = true;
    qint64 m_target = 0;
    qint32 m_speed = 0;
    bool m_stopping = false;
};

// home [--positive]
class HomeCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit HomeCommand(CliContext *c) : CliCommand(QStringLiteral("home"), c) {}
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;
    void interrupt(int signalNumber) override;

private:
    bool m_positive = false;
    bool m_stopping = false;
};

} // namespace dd
