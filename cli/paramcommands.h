#pragma once

#include "cli/clicommand.h"

// Parameter commands: get PARAM ..., set PARAM=VALUE ...

namespace dd {

class GetCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit GetCommand(CliContext *c)
        : CliCommand(QStringLiteral("get"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;

private:
    QList<int> m_indices;
};

class SetCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit SetCommand(CliContext *c)
        : CliCommand(QStringLiteral("set"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;
    // Writes in flight finish (each is verified); nothing new is started.
    void interrupt(int) override { }

private:
    QList<ParameterWrite> m_writes;
};

} // namespace dd
