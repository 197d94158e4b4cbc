#pragma once

#include <QCoreApplication>
#include <QString>

namespace dd {

struct CliContext;
struct CliGlobals;
struct DriveIdentity;
struct JournalKey;
struct RecordVerification;
struct RecordEeOperation;
struct RestoreReport;
class ParameterDictionary;

// The CLI's side of the verification journal (core/report/verificationjournal.h): set,
// restore, apply, ee and backup note what they verified or saved for the drive at
// --address, so that a later `report` can put it in the commissioning record. The drive is
// keyed by --machine, the link and what it identified itself as (JournalKey). A journal
// that cannot be written is said on stderr and changes nothing else.
class CliJournal
{
    Q_DECLARE_TR_FUNCTIONS(dd::CliJournal)
public:
    static void verification(CliContext *context, const RecordVerification &verification);
    static void ee(CliContext *context, const RecordEeOperation &operation);
    static void backup(CliContext *context, const QString &role, const QString &path, const QString &checksum);
    // A restore of the drive `key` names (restore, fleet restore): VerificationJournal::recordRestore.
    static void restore(CliContext *context, const JournalKey &key, const RestoreReport &report,
                        const ParameterDictionary &dictionary, const QString &path, const QString &checksum);

    // The link as the journal key names it: the port or CAN interface; with --sim
    // "sim" (the simulator's pseudo-terminal changes every run) and the --sim-state file.
    static QString link(const CliGlobals &globals);
    // The key of the drive at --address (identified by then: CliCommand::begin).
    static JournalKey key(CliContext *context);
    // The key of the drive at `address` that identified itself as `identity` (fleet commands).
    static JournalKey key(CliContext *context, const DriveIdentity &identity, int address);
};

} // namespace dd
