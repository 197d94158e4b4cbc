#include "cli/clicommand.h"

#include "core/drive/drive.h"
#include "core/drive/driveconnection.h"
#include "core/drive/familybackend.h" // driveconnection.h needs it complete (QPointer)
#include "core/protocol/familytraits.h"

namespace dd {

Drive *CliContext::drive() const
{
    Drive *d = connection ? connection->drive(globals.address) : nullptr;
    if (d && dictionary && d->dictionary() != dictionary)
        d->setDictionary(dictionary);
    return d;
}

CliCommand::CliCommand(const QString &name, CliContext *context, QObject *parent)
    : QObject(parent)
    , m_name(name)
    , m_ctx(context)
{
}

void CliCommand::begin()
{
    if (!identifyFirst())
        return start();
    onFinished(drive()->refreshIdentity(), [this](DriveReply *r) {
        if (m_done)
            return;
        const QStringList warnings = r->info().value(QStringLiteral("warnings")).toStringList();
        for (const QString &w : warnings)
            out()->note(tr("Warning: %1").arg(w));
        if (!r->ok()) {
            if (!identifyMayFail())
                return fail(r->error());
            out()->note(tr("The drive did not identify itself (%1); going on.").arg(r->error().message));
        }
        start();
    });
}

void CliCommand::interrupt(int)
{
    fail({ErrorCode::Cancelled, tr("Interrupted.")});
}

void CliCommand::linkLost(const Error &why)
{
    Error e = why;
    if (e.message.isEmpty())
        e.message = tr("The link to the drive was lost. Check the adapter and its cable.");
    if (e.code == ErrorCode::None)
        e.code = ErrorCode::LinkClosed;
    fail(e);
}

void CliCommand::succeed(const QJsonObject &json, const QString &text, CliExit code)
{
    if (m_done)
        return;
    QJsonObject doc{{QStringLiteral("command"), m_name}, {QStringLiteral("ok"), true}};
    if (code != CliExit::Ok)
        doc.insert(QStringLiteral("exitCode"), int(code));
    for (auto it = json.begin(); it != json.end(); ++it)
        doc.insert(it.key(), it.value());
    if (m_motionSwitchesPowerOn) {
        doc.insert(QStringLiteral("powerStageOn"), true);
        out()->note(powerStaysOnNote());
    }
    out()->result(doc, text);
    finish(code);
}

void CliCommand::fail(const Error &error, const QJsonObject &partial, std::optional<CliExit> code)
{
    if (m_done)
        return;
    const CliExit c = code.value_or(exitForFailure(error));
    Error shown = error;
    if (error.code == ErrorCode::Timeout && m_name != QLatin1String("scan"))
        shown.message += QLatin1Char(' ') + tr("If the address or baud rate may be wrong, try: drivedesk-cli ... scan");
    if (m_motionSwitchesPowerOn)
        out()->note(powerStaysOnNote());
    out()->failure(m_name, int(c), shown, partial);
    finish(c);
}

CliExit CliCommand::exitForFailure(const Error &error) const
{
    return exitFor(error) == CliExit::Ok ? CliExit::DriveFailed : exitFor(error);
}

void CliCommand::finish(CliExit code)
{
    if (m_done)
        return;
    m_done = true;
    emit done(int(code));
}

bool CliCommand::expectArguments(const CliInvocation &inv, int min, int max, const QString &what, QString *error) const
{
    const int n = int(inv.positionals.size());
    if (n < min) {
        *error = tr("\"%1\" needs %2. See: drivedesk-cli %1 --help").arg(m_name, what);
        return false;
    }
    if (max >= 0 && n > max) {
        *error = tr("\"%1\": unexpected argument \"%2\". See: drivedesk-cli %1 --help")
                     .arg(m_name, inv.positionals.at(max));
        return false;
    }
    return true;
}

void CliCommand::onFinished(DriveReply *reply, std::function<void(DriveReply *)> handler)
{
    connect(reply, &DriveReply::finished, this, [reply, handler = std::move(handler)] {
        handler(reply);
        reply->deleteLater();
    });
}

bool CliCommand::motionMaySwitchPowerOn(bool enableGiven)
{
    const FamilyTraits &t = familyTraits(context()->globals.connection.family);
    if (!t.motionEnables || drive()->status().enabled)
        return true;
    if (!enableGiven) {
        fail({ErrorCode::InvalidArgument,
              tr("On %1 drives a motion command switches the power stage on by itself, and whether it is on "
                 "cannot be read back. Add --enable to allow it: the power stage is then on, and stays on "
                 "afterwards (the motor holds its position) until `enable off`. Nothing was sent after "
                 "identifying the drive.")
                  .arg(t.displayName())},
             {}, CliExit::Usage);
        return false;
    }
    m_motionSwitchesPowerOn = true;
    out()->note(tr("--enable: this command switches the power stage on."));
    return true;
}

QString CliCommand::powerStaysOnNote() const
{
    return tr("The power stage may be on (this command was allowed to switch it on) and stays so, the motor "
              "holding its position; `enable off` switches it off.");
}

} // namespace dd
