#pragma once

#include "cli/cliexit.h"
#include "cli/cliglobals.h"
#include "cli/clioutput.h"

#include "core/drive/drivereply.h"

#include <QJsonObject>
#include <QObject>
#include <functional>
#include <memory>
#include <optional>

namespace dd {

class Drive;
class DriveConnection;
class ParameterDictionary;

// What every command sees: the global options, the output, and (once the link is open)
// the connection.
struct CliContext
{
    CliGlobals globals;
    CliOutput *out = nullptr;
    DriveConnection *connection = nullptr;
    // --dictionary FILE, or the family's (user's or bundled) dictionary; never null once
    // the runner has loaded it. Commands check names and values against it in prepare().
    std::shared_ptr<const ParameterDictionary> dictionary;

    // The drive at --address, with `dictionary` set on it.
    Drive *drive() const;
};

// One command of the CLI. The runner calls prepare() before the link is opened: it must
// interpret and check every argument and input file there (a failure is exit code 2 and
// nothing is sent). Then start(); the command prints its result and emits done() once.
class CliCommand : public QObject
{
    Q_OBJECT
public:
    CliCommand(const QString &name, CliContext *context, QObject *parent = nullptr);

    QString name() const { return m_name; }
    bool isDone() const { return m_done; }

    // Interpret the arguments, no I/O on the link. false: bad usage or input (*error says why).
    virtual bool prepare(const CliInvocation &inv, QString *error) = 0;
    // Whether the command needs an open link (all but a few do).
    virtual bool needsLink() const { return true; }
    // Whether it talks to the drive at --address (all but scan).
    virtual bool needsDrive() const { return true; }
    // Whether it works on several drives (--address 1,2,5 or --all).
    virtual bool takesManyDrives() const { return false; }
    // Whether begin() identifies the drive before start(), and whether start() runs anyway
    // when that fails (stop: a stop is always sent).
    virtual bool identifyFirst() const { return needsDrive(); }
    virtual bool identifyMayFail() const { return false; }
    // Runs the command: for commands that talk to a drive, identify it first (this also
    // waits until the link is up, e.g. a CAN bus still connecting), then start().
    void begin();
    virtual void start() = 0;
    // SIGINT / SIGTERM. Default: give up (exit 1); commands that move the axis stop it.
    virtual void interrupt(int signalNumber);
    // The port or bus went away while the command ran.
    virtual void linkLost(const Error &why);

signals:
    void done(int exitCode);

protected:
    CliContext *context() const { return m_ctx; }
    CliOutput *out() const { return m_ctx->out; }
    Drive *drive() const { return m_ctx->drive(); }

    // The command did its work; `code` is its answer (diff: 1 = different).
    void succeed(const QJsonObject &json, const QString &text, CliExit code = CliExit::Ok);
    // Report `error` and finish with `code` (default: the code for the error).
    void fail(const Error &error, const QJsonObject &partial = {}, std::optional<CliExit> code = std::nullopt);
    // The exit code of a failure when fail() is given none (diff: 2 for any trouble, since
    // its 1 means "different").
    virtual CliExit exitForFailure(const Error &error) const;
    void finish(CliExit code);
    // Checks the number of arguments; false with a message when it does not fit.
    bool expectArguments(const CliInvocation &inv, int min, int max, const QString &what, QString *error) const;

    // A motion command on a family whose motion switches the power stage on by itself
    // (FamilyTraits::motionEnables: servo-can) runs only with --enable, since nobody can see
    // whether the stage is on. False, with the command failed (exit 2, nothing sent), when it
    // may not run; true when it may, noting that the stage will be on.
    bool motionMaySwitchPowerOn(bool enableGiven);
    // Once allowed, every result says that the stage may be on and stays so (a note; JSON
    // "powerStageOn": true on success).
    QString powerStaysOnNote() const;

    // Call `handler` when `reply` finishes (from the event loop), then delete the reply.
    void onFinished(DriveReply *reply, std::function<void(DriveReply *)> handler);

private:
    QString m_name;
    CliContext *m_ctx;
    bool m_done = false;
    bool m_motionSwitchesPowerOn = false;
};

} // namespace dd
