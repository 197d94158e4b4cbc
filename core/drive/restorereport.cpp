#include "core/drive/restorereport.h"

namespace dd {

const ParameterWriteResult *RestoreReport::result(int index) const
{
    for (const ParameterWriteResult &r : results)
        if (r.index == index)
            return &r;
    return nullptr;
}

RestoreReport::Outcome RestoreReport::outcome(int index) const
{
    const ParameterWriteResult *r = result(index);
    if (!r)
        return Outcome::NotAttempted;
    if (r->verified)
        return Outcome::Verified;
    if (r->readBackFailed && r->readable)
        return Outcome::Unconfirmed;
    if (!r->written)
        return Outcome::Failed;
    return r->readable ? Outcome::Mismatch : Outcome::WrittenOnly;
}

QList<int> RestoreReport::indices(Outcome o) const
{
    QList<int> out;
    for (const DiffEntry &e : selected)
        if (outcome(e.index) == o)
            out << e.index;
    return out;
}

bool RestoreReport::isComplete() const
{
    if (dryRun)
        return false;
    for (const DiffEntry &e : selected) {
        const Outcome o = outcome(e.index);
        if (o != Outcome::Verified && o != Outcome::WrittenOnly)
            return false;
    }
    return true;
}

QList<int> RestoreReport::written() const
{
    QList<int> out;
    for (const DiffEntry &e : selected) {
        const Outcome o = outcome(e.index);
        if (o == Outcome::Verified || o == Outcome::WrittenOnly || o == Outcome::Mismatch)
            out << e.index;
    }
    return out;
}

QList<int> RestoreReport::notWritten() const
{
    QList<int> out;
    for (const DiffEntry &e : selected) {
        const Outcome o = outcome(e.index);
        if (o == Outcome::Failed || o == Outcome::NotAttempted)
            out << e.index;
    }
    return out;
}

QString RestoreReport::outcomeId(Outcome o)
{
    switch (o) {
    case Outcome::Verified: return QStringLiteral("verified");
    case Outcome::WrittenOnly: return QStringLiteral("written-only");
    case Outcome::Mismatch: return QStringLiteral("mismatch");
    case Outcome::Failed: return QStringLiteral("failed");
    case Outcome::NotAttempted: return QStringLiteral("not-attempted");
    case Outcome::Unconfirmed: return QStringLiteral("unconfirmed");
    }
    return {};
}

} // namespace dd
