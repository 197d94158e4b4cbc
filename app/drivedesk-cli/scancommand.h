#pragma once

#include "clicommand.h"

#include "drive/discovery.h"

#include <QJsonArray>

namespace dd {

// scan [--from A] [--to B] [--bauds 9600,19200,...]
class ScanCommand : public CliCommand
{
    Q_OBJECT
public:
    explicit ScanCommand(CliContext *c) : CliCommand(QStringLiteral("scan"), c) {}
    bool prepare(const CliInvocation &inv, QString *error) override;
    void start() override;
    void interrupt(int signalNumber) override;
    bool needsDrive() const override { return false; }

    // The rates a serial scan tries when neither --bauds nor --baud is given.
    static QList<int> usualBauds(Family family);

private:
    void onFinished(const Error &error);

    ScanOptions m_options;
    Discovery *m_discovery = nullptr;
    QJsonArray m_found;
    bool m_interrupted = false;
};

} // namespace dd
