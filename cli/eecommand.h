#pragma once

#include "cli/clicommand.h"

namespace dd {

// ee set|rd|ba|rs|def: servo-modbus EEPROM operations; waits for completion.
class EeCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit EeCommand(CliContext *c)
        : CliCommand(QStringLiteral("ee"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;
    // An EEPROM operation in progress is not abandoned: the drive finishes it anyway.
    void interrupt(int) override;

private:
    EeOperation m_op = EeOperation::Save;
};

} // namespace dd
