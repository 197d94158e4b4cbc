#pragma once

#include <QString>
#include <QtGlobal>

namespace dd {

// The health of one drive's link as a commissioning record shows it: core/link's LinkHealth
// figures for the drive's address over some span (`scope` says which) — requests and
// replies, turnaround, timeouts, checksum errors, late or duplicated replies, retries,
// requests sent on a line that was never quiet — and the operations on the drive that failed.
struct RecordLinkHealth
{
    bool measured = false; // false: nothing was counted (shown as "not measured")
    QString scope;         // in the record's language: "while this record was made", ...
    int requests = 0;
    int answered = 0;
    int timeouts = 0;
    int checksumErrors = 0;
    int lateReplies = 0; // stale, late or duplicated replies dropped
    int retries = 0;
    double turnaroundMinMs = 0, turnaroundMedianMs = 0, turnaroundMaxMs = 0; // when answered > 0
    int errors = 0;        // operations that failed (timeouts, exceptions)
    int busyLineSends = 0; // requests sent on a line that was never quiet
};

} // namespace dd
