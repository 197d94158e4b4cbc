#include "cli/restoredescribe.h"

#include "cli/clivalues.h"

#include "core/params/parameterdictionary.h"

namespace dd {

QJsonArray RestoreDescribe::selected(const ParameterDictionary &dict, const RestoreReport &r,
                                     QList<QPair<QString, QString>> *rows)
{
    QJsonArray list;
    for (const DiffEntry &e : r.selected) {
        QJsonObject o{{QStringLiteral("index"), e.index},
                      {QStringLiteral("key"), e.key},
                      {QStringLiteral("from"), CliValues::json(e.driveValue)},
                      {QStringLiteral("to"), CliValues::json(e.fileValue)}};
        const QString state = r.dryRun ? tr("would be written") : outcome(r, e.index, &o);
        list.append(o);
        if (rows)
            rows->append({dict.label(e.index),
                          tr("%1 -> %2  %3").arg(CliValues::text(e.driveValue), CliValues::text(e.fileValue), state)});
    }
    return list;
}

QString RestoreDescribe::outcome(const RestoreReport &r, int index, QJsonObject *o)
{
    using O = RestoreReport::Outcome;
    const O outcome = r.outcome(index);
    o->insert(QStringLiteral("result"), RestoreReport::outcomeId(outcome));
    const ParameterWriteResult *res = r.result(index);
    if (res && res->readable && res->written && !res->readBackFailed)
        o->insert(QStringLiteral("readBack"), double(res->readBack));
    switch (outcome) {
    case O::Verified: return tr("verified");
    case O::WrittenOnly: return tr("written (write-only: cannot be read back)");
    case O::Mismatch: return tr("WRITTEN, READ BACK %1").arg(res ? res->readBack : 0);
    case O::Failed: return tr("NOT WRITTEN: %1").arg(res ? res->error : QString());
    case O::NotAttempted: return tr("NOT WRITTEN (not attempted)");
    case O::Unconfirmed:
        return res && res->written ? tr("WRITTEN, NOT VERIFIED (no answer to the read-back)")
                                   : tr("UNKNOWN: %1").arg(res ? res->error : QString());
    }
    return QString();
}

void RestoreDescribe::insertOutcomes(const ParameterDictionary &dict, const RestoreReport &r, QJsonObject *json)
{
    using O = RestoreReport::Outcome;
    if (r.dryRun)
        return;
    auto keys = [&dict](const QList<int> &indices) {
        QJsonArray a;
        for (int i : indices) {
            const ParameterInfo *p = dict.byIndex(i);
            a.append(p ? p->key : QString::number(i));
        }
        return a;
    };
    json->insert(QStringLiteral("verified"), keys(r.indices(O::Verified)));
    json->insert(QStringLiteral("written"), keys(r.written()));
    json->insert(QStringLiteral("notWritten"), keys(r.notWritten()));
    json->insert(QStringLiteral("mismatch"), keys(r.indices(O::Mismatch)));
    json->insert(QStringLiteral("unconfirmed"), keys(r.indices(O::Unconfirmed)));
}

QStringList RestoreDescribe::incomplete(const ParameterDictionary &dict, const RestoreReport &r)
{
    auto labels = [&dict](const QList<int> &indices) {
        QStringList l;
        for (int i : indices)
            l << dict.label(i);
        return l;
    };
    QStringList lines;
    const QStringList w = labels(r.written());
    const QStringList n = labels(r.notWritten());
    lines << tr("Written: %1").arg(w.isEmpty() ? tr("none") : w.join(QLatin1String(", ")));
    lines << tr("Not written: %1").arg(n.isEmpty() ? tr("none") : n.join(QLatin1String(", ")));
    const QStringList u = labels(r.indices(RestoreReport::Outcome::Unconfirmed));
    if (!u.isEmpty())
        lines << tr("Unknown (read them again): %1").arg(u.join(QLatin1String(", ")));
    return lines;
}

} // namespace dd
