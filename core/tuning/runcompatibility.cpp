#include "core/tuning/runcompatibility.h"

#include "core/tuning/tuningrun.h"

#include <QHash>
#include <QSet>

namespace dd {

QStringList RunCompatibility::snapshotProblems(const TuningRun &run)
{
    QStringList out;
    QSet<int> indices;
    QSet<QString> keys;
    for (const TuningSnapshotEntry &e : run.tuning) {
        const QString key = e.key.toLower();
        if (indices.contains(e.index) || keys.contains(key))
            out << tr("%1 (index %2) is listed twice in the tuning snapshot of %3.")
                       .arg(e.key)
                       .arg(e.index)
                       .arg(run.label);
        indices.insert(e.index);
        keys.insert(key);
    }
    return out;
}

QString RunCompatibility::stepSize(const TuningRun &run)
{
    const QJsonObject &p = run.testParameters;
    if (run.test == QLatin1String("position-step") && p.contains(QLatin1String("distance")))
        return tr("%1 counts").arg(p.value(QLatin1String("distance")).toDouble());
    if (run.test != QLatin1String("capture") && p.contains(QLatin1String("speed")))
        return tr("%1 r/min").arg(p.value(QLatin1String("speed")).toDouble());
    return {};
}

QStringList RunCompatibility::differences(const TuningRun &a, const TuningRun &b)
{
    QStringList out;
    if (a.family != b.family)
        out << tr("%1 was taken on a %2 drive, %3 on a %4 drive.").arg(a.label, a.family, b.label, b.family);
    else if (!a.model.isEmpty() && !b.model.isEmpty() && a.model.compare(b.model, Qt::CaseInsensitive) != 0)
        out << tr("%1 was taken on a %2, %3 on a %4.").arg(a.label, a.model, b.label, b.model);
    QHash<int, const TuningSnapshotEntry *> byIndex;
    for (const TuningSnapshotEntry &e : a.tuning)
        byIndex.insert(e.index, &e);
    for (const TuningSnapshotEntry &eb : b.tuning) {
        const TuningSnapshotEntry *ea = byIndex.value(eb.index);
        if (ea && (ea->key.compare(eb.key, Qt::CaseInsensitive) != 0 || ea->role != eb.role)) {
            out << tr("The runs were recorded with different dictionaries: index %1 is %2 (%3) in %4 and %5 (%6) "
                      "in %7.")
                       .arg(eb.index)
                       .arg(ea->key, ea->role.isEmpty() ? tr("no tuning role") : ea->role, a.label, eb.key,
                            eb.role.isEmpty() ? tr("no tuning role") : eb.role, b.label);
            break;
        }
    }
    if (a.test != b.test) {
        out << tr("%1 is a %2, %3 a %4: different tests do not compare.").arg(a.label, a.test, b.label, b.test);
    } else {
        const QString sa = stepSize(a), sb = stepSize(b);
        if (sa != sb)
            out << tr("%1 and %2 are steps of different sizes (%3, %4): their metrics do not compare.")
                       .arg(a.label, b.label, sa, sb);
    }
    return out;
}

} // namespace dd
