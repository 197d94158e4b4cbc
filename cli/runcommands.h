#pragma once

#include "cli/clicommand.h"
#include "core/tuning/tuningrun.h"

namespace dd {

// drivedesk-cli runs RUN.ddrun [RUN2.ddrun ...]: the metrics side by side and the tuning
// parameters that differ between consecutive runs ("P60 30 → 60: overshoot 9 % → 32 %").
// Files only: no link.
class RunsCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit RunsCommand(CliContext *c)
        : CliCommand(QStringLiteral("runs"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    bool needsLink() const override { return false; }
    bool needsDrive() const override { return false; }
    void start() override;

private:
    QList<TuningRun> m_runs;
};

// drivedesk-cli spectrum RUN.ddrun CHANNEL [--peaks N]: the channel's amplitude spectrum,
// its peaks, the window and the resolution. Files only: no link.
class SpectrumCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit SpectrumCommand(CliContext *c)
        : CliCommand(QStringLiteral("spectrum"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    bool needsLink() const override { return false; }
    bool needsDrive() const override { return false; }
    void start() override;

private:
    TuningRun m_run;
    QString m_channel;
    int m_peaks = 5;
    double m_fromHz = 0.0;
    bool m_between = false; // --between T1:T2: only the samples of that stretch
    double m_t1 = 0.0;
    double m_t2 = 0.0;
};

} // namespace dd

namespace dd {

class RunParameterApply;

// drivedesk-cli apply-run RUN.ddrun [--dry-run] [--force]: writes the run's tuning snapshot
// to the drive where it differs, each write read back, with a report like restore's.
class ApplyRunCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit ApplyRunCommand(CliContext *c)
        : CliCommand(QStringLiteral("apply-run"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;
    void interrupt(int) override;

private:
    void report(const Error &error);

    QString m_path;
    TuningRun m_run;
    bool m_dryRun = false;
    bool m_force = false;
    RunParameterApply *m_apply = nullptr;
};

} // namespace dd
