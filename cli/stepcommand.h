#pragma once

#include "cli/clicommand.h"
#include "core/tuning/steplimits.h"
#include "core/tuning/stepspec.h"

namespace dd {

class StepTest;
struct StepResult;

// drivedesk-cli step velocity SPEED --duration S --max-speed V --max-travel N [-o RUN.ddrun]
//               step position DISTANCE --speed V --max-travel N [-o RUN.ddrun]
//               step reversal SPEED --duration S --max-speed V --max-travel N [-o RUN.ddrun]
// A step-response test (core StepTest, docs/tuning.md): refuses to run without its limits
// (exit 2, nothing sent), prints the metrics, saves the run. Ctrl-C stops the axis.
class StepCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit StepCommand(CliContext *c);
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;
    void interrupt(int signalNumber) override;
    void linkLost(const Error &why) override;

private:
    void onFinished(const StepResult &result);

    StepSpec m_spec;
    StepLimits m_limits;
    QString m_output;
    QString m_notes;
    StepTest *m_test = nullptr;
    bool m_interrupted = false;
    bool m_enable = false; // --enable: the motion may switch the power stage on
};

} // namespace dd
