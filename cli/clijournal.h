#pragma once

#include <QCoreApplication>
#include <QString>

namespace dd {

struct CliContext;
struct RecordVerification;

// The CLI's side of the verification journal (core/report/verificationjournal.h): restore,
// set and backup note what they verified or saved for the drive at --address, so that a
// later `report` can put it in the commissioning record. A journal that cannot be written
// is said on stderr and changes nothing else.
class CliJournal
{
    Q_DECLARE_TR_FUNCTIONS(dd::CliJournal)
public:
    static void verification(CliContext *context, const RecordVerification &verification);
    static void backup(CliContext *context, const QString &role, const QString &path, const QString &checksum);
};

} // namespace dd
