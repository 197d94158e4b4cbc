#pragma once

#include "core/common/error.h"
#include "core/report/journalkey.h"

#include <QCoreApplication>
#include <QString>

namespace dd {

class DriveHub;
struct DriveContext;
struct DriveIdentity;
struct RecordEeOperation;
struct RecordVerification;

// The GUI's side of the verification journal (core/report/verificationjournal.h): every
// GUI write path (Parameters, Tuning, restore, apply, fleet apply, EE operations) notes what
// it verified or saved here, keyed by the drive's identity, the connection's port or CAN
// interface and the machine / project name of the commissioning record's form (persisted
// in the record dialog's settings). Returns the journal's error for the panel to show.
class GuiJournal
{
    Q_DECLARE_TR_FUNCTIONS(dd::GuiJournal)
public:
    // The machine / project name the engineer set in File → Commissioning record…
    static QString machine();

    // `identity` as the drive reported it (DriveResult::identity); its family and address
    // are taken from `context` when the result carries none.
    static JournalKey key(const DriveHub *hub, int connectionId, int address, const DriveIdentity &identity);
    static JournalKey key(const DriveContext &context, const DriveIdentity &identity);
    static Error verification(const DriveContext &context, const DriveIdentity &identity,
                              const RecordVerification &verification);
    static Error eeOperation(const DriveContext &context, const DriveIdentity &identity,
                             const RecordEeOperation &operation);
    static Error backup(const DriveContext &context, const DriveIdentity &identity, const QString &role,
                        const QString &path, const QString &checksum);
};

} // namespace dd
