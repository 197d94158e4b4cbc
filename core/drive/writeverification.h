#pragma once

#include "core/common/error.h"
#include "core/drive/drivetypes.h"

#include <QCoreApplication>
#include <QList>
#include <QString>

#include <optional>

namespace dd {

// "Every write is read back", decided and worded once for every family.
//
// A drive writes a parameter, reads it back, and hands what it learnt to add() as a Check;
// add() turns it into a ParameterWriteResult (outcome, written, verified, readBack,
// readBackFailed, error, with one wording per outcome):
//   - read back equal to the value written: Verified, whatever became of the write's
//     answer (a lost or damaged answer to a write the drive carried out);
//   - read back different: Mismatch if the drive took the write, NotWritten if the write
//     failed (the drive did not take the value);
//   - no read-back: NotWritten if none was tried (the drive refused the write, or it was
//     never sent); if it was tried and failed, ReadBackFailed when the drive had accepted
//     the write, else Unknown (not confirmed, not read back: what the drive holds is
//     unknown);
//   - a write-only setting (not readable): WriteOnly once the drive accepted it, else
//     NotWritten.
// summary() is the error a batch finishes with: the first write in the batch that failed
// (NotWritten, Unknown, ReadBackFailed), with the code of its cause and the parameter
// named; else VerifyMismatch counting the mismatches and naming the first; else none
// (WriteOnly is not an error). A value type.
class WriteVerification
{
    Q_DECLARE_TR_FUNCTIONS(dd::WriteVerification)
public:
    struct Check
    {
        int index = 0;
        qint64 requested = 0;
        QString label;                  // names the parameter in summary(): "PA5", "P30", ...
        bool readable = true;           // false: a write-only setting, nothing reads it back
        bool acknowledged = true;       // false: the protocol does not answer writes (servo-can),
                                        // so only the read-back tells whether the drive took it
        Error writeError;               // the answer to the write; none: the drive accepted it
        std::optional<qint64> readBack; // the value read back after the write
        Error readError;                // why there is no read-back; none: none was tried
        int attempts = 1;               // how often the write was sent (named when more than 1)
    };

    // Classifies `check`, keeps it for summary() and returns the result.
    ParameterWriteResult add(const Check &check);
    QList<ParameterWriteResult> results() const;
    Error summary() const;

    // The result of one write; `cause`, if given, receives the error behind a failure.
    static ParameterWriteResult classify(const Check &check, Error *cause = nullptr);

private:
    struct Entry
    {
        ParameterWriteResult result;
        Error cause;
        QString label;
    };
    QList<Entry> m_entries;
};

} // namespace dd
