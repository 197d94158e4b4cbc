#pragma once

#include "cli/clicommand.h"

#include "core/drive/discovery.h"
#include "core/fleet/fleetdriveresult.h"

#include <QJsonObject>
#include <QList>
#include <QVector>

namespace dd {

class FleetTransfer;

// A command on several drives of the link: --address 1,2,5 (those drives, in that order) or
// --all (every drive a scan of the link finds, at the link's baud; --from/--to narrow the
// scan). The drives run back to back through one FleetTransfer; each drive's result is its
// own and the exit code is the worst drive's.
class FleetCommand : public CliCommand
{
    Q_OBJECT
public:
    using CliCommand::CliCommand;
    bool needsDrive() const override { return false; }
    bool takesManyDrives() const override { return true; }
    void start() override;
    // No further drive is started; those under way finish and are reported.
    void interrupt(int signalNumber) override;
    // The drives under way fail (their reports say what they did), the rest are not
    // attempted; the report follows.
    void linkLost(const Error &why) override;

protected:
    bool prepareTargets(const CliInvocation &inv, QString *error);
    // The drives, known without a scan (no --all).
    void setTargets(const QList<int> &addresses)
    {
        m_all = false;
        m_addresses = addresses;
    }
    // The drives are known: start the transfer (m_transfer made by newTransfer()).
    virtual void run(const QList<int> &addresses) = 0;
    FleetTransfer *newTransfer(const QList<int> &addresses);
    // Exit code of one drive's result, and the worst of all.
    virtual CliExit exitOf(const FleetDriveResult &result) const;
    CliExit worstExit() const;
    // address, result, exitCode, firmware, model; failed: error, stoppedAt.
    QJsonObject driveJson(const FleetDriveResult &result) const;
    // "drive 3: FAILED while reading: ..." / "drive 3: not attempted".
    QString failureLine(const FleetDriveResult &result) const;
    // Finish: ok when every drive's exit code is 0, else a failure naming the drives.
    void conclude(const QJsonObject &json, const QString &text);

    FleetTransfer *m_transfer = nullptr;
    bool m_all = false;

private:
    void scan();
    QList<int> m_addresses;
    ScanOptions m_scan;
    Discovery *m_discovery = nullptr;
    bool m_interrupted = false;
};

} // namespace dd
