#pragma once

#include <QString>
#include <QtGlobal>

namespace dd {

// The health of the link a drive is on, as counted over some span (`scope` says which):
// frames sent and received, frames discarded (noise, bad checksum, late replies), retries
// and failed operations. The link work's counters feed this after merge.
struct RecordLinkHealth
{
    bool measured = false; // false: nothing was counted (shown as "not measured")
    QString scope;         // in the record's language: "while this record was made", ...
    quint64 framesSent = 0;
    quint64 framesReceived = 0;
    quint64 discarded = 0;
    quint64 retries = 0;
    quint64 errors = 0; // operations that failed (timeouts, exceptions)
};

} // namespace dd
