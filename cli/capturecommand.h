#pragma once

#include "cli/clicommand.h"
#include "core/tuning/capturesettings.h"

#include <QTimer>

namespace dd {

class CaptureSession;
struct CaptureData;

// drivedesk-cli capture CHANNEL,... [--trigger EXPR] [--pre PERCENT] [--duration S]
//                [--mode single|auto] [--timeout S] [--notes TEXT] -o RUN.ddrun
// Samples the channels as fast as the link allows, waits for the trigger, records, reads
// the drive's tuning parameters (the dictionary's "tuning" group) and saves a run file.
class CaptureCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit CaptureCommand(CliContext *c)
        : CliCommand(QStringLiteral("capture"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;
    void interrupt(int signalNumber) override;

private:
    void onCaptured(const CaptureData &capture);

    QStringList m_channels;
    CaptureSettings m_settings;
    QString m_output;
    QString m_notes;
    CaptureSession *m_session = nullptr;
    QTimer m_giveUp; // single mode without a trigger: Ctrl-C, or this much past the time-out
};

} // namespace dd
