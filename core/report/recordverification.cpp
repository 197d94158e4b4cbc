#include "core/report/recordverification.h"

namespace dd {

bool RecordVerification::Entry::isVerified() const
{
    return outcome == QLatin1String("verified") || outcome == QLatin1String("written-only");
}

int RecordVerification::failedCount() const
{
    int n = 0;
    for (const Entry &e : entries)
        if (!e.isVerified())
            ++n;
    return n;
}

} // namespace dd
