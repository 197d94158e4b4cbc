#pragma once

#include "cli/clicommand.h"
#include "core/link/linkhealth.h"

namespace dd {

// `ping [--count N]`: asks the drive for its status N times, one request at a time, and
// reports the link's health from the traffic (LinkHealth): turnaround min / median / max,
// timeouts, checksum errors, late or duplicated replies, retries, and the reply allowance
// and inter-request gap it recommends. Exit 1 when the drive answered none.
class PingCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit PingCommand(CliContext *c)
        : CliCommand(QStringLiteral("ping"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    bool identifyFirst() const override { return false; } // a silent drive is a result
    void start() override;

private:
    void next();
    void report();

    int m_count = 10;
    int m_sent = 0;
    int m_failed = 0;
    Error m_lastError;
    LinkHealth m_health;
};

} // namespace dd
