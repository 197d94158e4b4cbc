#pragma once

#include "cli/clicommand.h"

#include "core/drive/discovery.h"

#include <QJsonArray>

namespace dd {

// scan [--from A] [--to B] [--bauds 9600,19200,...]
class ScanCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit ScanCommand(CliContext *c)
        : CliCommand(QStringLiteral("scan"), c)
    {
    }
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;
    void interrupt(int signalNumber) override;
    bool needsDrive() const override { return false; }
    // The scan prepare() planned: address range and baud sweep.
    const ScanOptions &options() const { return m_options; }

private:
    void onFinished(const Error &error);

    ScanOptions m_options;
    Discovery *m_discovery = nullptr;
    QJsonArray m_found;
    bool m_interrupted = false;
};

} // namespace dd
