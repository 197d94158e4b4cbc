#pragma once

#include <QDateTime>
#include <QString>

namespace dd {

// The last EEPROM operation on a drive (EE-Set, EE-rd, EE-bA, EE-rS, EE-dEF; servo-modbus),
// as the GUI's EE tab or the CLI's `ee` reported it: kept in the VerificationJournal apart
// from the last restore or write (an EE-Set after a write must not hide the write) and
// shown in the commissioning record.
struct RecordEeOperation
{
    QString operation; // the mnemonic: "EE-Set", "EE-dEF", ...; empty: none recorded
    QDateTime when;
    bool ok = false;
    QString message; // why it failed; "" when it succeeded

    bool isEmpty() const { return operation.isEmpty(); }
};

} // namespace dd
