#include "core/drive/writeverification.h"

namespace dd {

namespace {

bool isFailure(WriteOutcome o)
{
    return o == WriteOutcome::NotWritten || o == WriteOutcome::Unknown || o == WriteOutcome::ReadBackFailed;
}

} // namespace

ParameterWriteResult WriteVerification::classify(const Check &check, Error *cause)
{
    ParameterWriteResult r;
    r.index = check.index;
    r.requested = check.requested;
    r.readable = check.readable;
    Error why;
    const bool accepted = !check.writeError.isError();
    if (!check.readable) {
        if (accepted) {
            r.outcome = WriteOutcome::WriteOnly;
            r.written = true;
            r.error = tr("Not readable: the drive cannot report this setting; %1 is kept as the "
                         "last value written.")
                          .arg(check.requested);
        } else {
            r.outcome = WriteOutcome::NotWritten;
            r.error = check.writeError.message;
            why = check.writeError;
        }
    } else if (check.readBack) {
        r.readBack = *check.readBack;
        if (r.readBack == check.requested) {
            r.outcome = WriteOutcome::Verified;
            r.written = true;
            r.verified = true;
        } else if (!accepted) {
            r.outcome = WriteOutcome::NotWritten;
            r.error = check.writeError.message + QLatin1Char(' ')
                + tr("The drive did not take the value: it reads back %1.").arg(r.readBack);
            why = check.writeError;
        } else {
            r.outcome = WriteOutcome::Mismatch;
            r.written = true;
            r.error = tr("Wrote %1, but the drive reads back %2.").arg(check.requested).arg(r.readBack);
            if (check.attempts > 1)
                r.error += QLatin1Char(' ') + tr("Written %n time(s).", nullptr, check.attempts);
        }
    } else if (!accepted && !check.readError.isError()) {
        r.outcome = WriteOutcome::NotWritten;
        r.error = check.writeError.message;
        why = check.writeError;
    } else if (!accepted || !check.acknowledged) {
        r.outcome = WriteOutcome::Unknown;
        r.readBackFailed = true;
        why = accepted ? check.readError : check.writeError;
        r.error = tr("The write was not confirmed and could not be read back, so whether the drive "
                     "took the value is unknown: %1 Read it again.")
                      .arg(why.message);
    } else {
        r.outcome = WriteOutcome::ReadBackFailed;
        r.written = true;
        r.readBackFailed = true;
        r.error = tr("Written, but it could not be read back: %1").arg(check.readError.message);
        why = check.readError;
    }
    if (cause)
        *cause = why;
    return r;
}

ParameterWriteResult WriteVerification::add(const Check &check)
{
    Entry e;
    e.result = classify(check, &e.cause);
    e.label = check.label.isEmpty() ? QString::number(check.index) : check.label;
    m_entries.append(e);
    return e.result;
}

QList<ParameterWriteResult> WriteVerification::results() const
{
    QList<ParameterWriteResult> out;
    for (const Entry &e : m_entries)
        out.append(e.result);
    return out;
}

Error WriteVerification::summary() const
{
    const Entry *firstMismatch = nullptr;
    int mismatches = 0;
    for (const Entry &e : m_entries) {
        if (isFailure(e.result.outcome)) {
            Error out = e.cause;
            if (!out.isError()) // a Check without the error behind it: still not verified
                out.code = ErrorCode::VerifyMismatch;
            out.message = tr("%1: %2").arg(e.label, e.result.error);
            return out;
        }
        if (e.result.outcome == WriteOutcome::Mismatch) {
            if (!firstMismatch)
                firstMismatch = &e;
            ++mismatches;
        }
    }
    if (!firstMismatch)
        return Error::none();
    return {ErrorCode::VerifyMismatch,
            tr("%n parameter(s) read back with another value than written (first: %1: %2). The drive "
               "may limit the value or not accept it in its present state, or the parameter may be "
               "read-only.",
               nullptr, mismatches)
                .arg(firstMismatch->label, firstMismatch->result.error)};
}

} // namespace dd
