#pragma once

#include "core/drive/drivetypes.h"

#include <QCoreApplication>
#include <QMap>
#include <QString>

namespace dd {

// Whether a drive still does what a step test asked of it (docs/tuning.md, "A STOP from
// anywhere"). The test tells it what it commanded; the samples of its capture and the
// drive's statuses are fed in; a non-empty (translated) answer says what the drive
// reports instead — the axis was stopped, disabled or given another command by someone
// else (another master, a PLC, the drive's own panel) — and the test must abort and send
// no further motion. What it watches, where the drive reports it:
//  - the "speed-command" channel: once it has read the commanded speed, any other value;
//  - the "status" channel's running bit (shuoke): once set, cleared;
//  - the status' running flag (heartbeat / status read): once running, at rest — while a
//    jog's first segment runs (a reversal passes through rest on purpose);
//  - the status' enable state: enabled, then disabled.
// No I/O; a value type.
class CommandWatch
{
    Q_DECLARE_TR_FUNCTIONS(dd::CommandWatch)

public:
    // Nothing is watched (before the motion, after the test's own stop).
    void idle();
    // The test commanded `speed` (a jog); `watchRunning`: at rest means stopped.
    void expectSpeed(double speed, bool watchRunning);
    bool isWatching() const { return m_active; }

    // A sample of the capture; "" while the drive follows the command.
    QString feedSample(const QMap<QString, double> &values);
    // A status of the drive; "" while it follows the command.
    QString feedStatus(const DriveStatus &status);

    // How far a reading may be from the command and still be it: 1 % of it, at least 1.
    static double tolerance(double speed);

private:
    bool m_active = false;
    bool m_watchRunning = false;
    double m_speed = 0.0;
    bool m_seenCommand = false;
    bool m_seenStatusBit = false;
    bool m_seenRunning = false;
    bool m_enableKnown = false;
    bool m_enabled = false;
};

} // namespace dd
