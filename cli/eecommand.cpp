#include "cli/eecommand.h"

#include "cli/clijournal.h"
#include "core/drive/drive.h"
#include "core/protocol/familytraits.h"
#include "core/report/verificationjournal.h"

namespace dd {

bool EeCommand::prepare(const CliInvocation &inv, QString *error)
{
    if (!expectArguments(inv, 1, 1, tr("an operation: set, rd, ba, rs or def"), error))
        return false;
    const auto op = eeFromText(inv.positionals.at(0));
    if (!op) {
        *error = tr("ee: unknown operation \"%1\". Operations: set, rd, ba, rs, def.").arg(inv.positionals.at(0));
        return false;
    }
    if (!familyTraits(context()->globals.connection.family).eeOperations) {
        QStringList families;
        for (const FamilyTraits *t : allFamilyTraits())
            if (t->eeOperations)
                families << t->id();
        *error = tr("EEPROM operations exist only on %1 drives (--family %1).").arg(families.join(QLatin1String(", ")));
        return false;
    }
    m_op = *op;
    return true;
}

void EeCommand::start()
{
    out()->note(tr("%1: %2 ...").arg(eeMnemonic(m_op), eeMeaning(m_op)));
    onFinished(drive()->eeOperation(m_op), [this](DriveReply *r) {
        const QJsonObject json{{QStringLiteral("operation"), eeMnemonic(m_op)}, {QStringLiteral("code"), int(m_op)}};
        CliJournal::ee(context(), VerificationJournal::fromEe(m_op, r->error())); // for the commissioning record
        if (!r->ok())
            return fail(r->error(), json);
        succeed(json, tr("%1 done.").arg(eeMnemonic(m_op)));
    });
}

void EeCommand::interrupt(int)
{
    out()->note(tr("Waiting for the EEPROM operation to finish (the drive completes it anyway)."));
}

} // namespace dd
