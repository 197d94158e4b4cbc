#include "ui/report/guijournal.h"

#include "core/drive/drivehub.h"
#include "core/drive/drivetypes.h"
#include "core/link/connectionsettings.h"
#include "core/report/verificationjournal.h"
#include "ui/workspace/drivecontext.h"

#include <QDateTime>
#include <QFileInfo>
#include <QSettings>

namespace dd {

namespace {

// The record dialog's settings group (ui/report/recorddialog.cpp) and its machine field.
const char *JournalSettingsGroup = "commissioningRecord";

} // namespace

QString GuiJournal::machine()
{
    QSettings s;
    s.beginGroup(QLatin1String(JournalSettingsGroup));
    return s.value(QStringLiteral("machine")).toString().trimmed();
}

JournalKey GuiJournal::key(const DriveHub *hub, int connectionId, int address, const DriveIdentity &identity)
{
    DriveIdentity id = identity;
    const ConnectionSettings settings = hub ? hub->connectionSettings(connectionId) : ConnectionSettings();
    if (id.address != address || id.link.isEmpty()) { // no identity came with the result
        id.family = settings.family;
        id.address = address;
    }
    return JournalKey::of(id, settings.linkName(), machine());
}

JournalKey GuiJournal::key(const DriveContext &context, const DriveIdentity &identity)
{
    DriveIdentity id = identity;
    if (id.address != context.address || id.link.isEmpty()) {
        id = DriveIdentity();
        id.family = context.family;
        id.address = context.address;
    }
    return key(context.hub, context.connectionId, context.address, id);
}

Error GuiJournal::verification(const DriveContext &context, const DriveIdentity &identity,
                               const RecordVerification &verification)
{
    return VerificationJournal().recordVerification(key(context, identity), verification);
}

Error GuiJournal::eeOperation(const DriveContext &context, const DriveIdentity &identity,
                              const RecordEeOperation &operation)
{
    return VerificationJournal().recordEeOperation(key(context, identity), operation);
}

Error GuiJournal::backup(const DriveContext &context, const DriveIdentity &identity, const QString &role,
                         const QString &path, const QString &checksum)
{
    return VerificationJournal().recordBackup(
        key(context, identity), {role, QFileInfo(path).absoluteFilePath(), checksum, QDateTime::currentDateTimeUtc()});
}

} // namespace dd
