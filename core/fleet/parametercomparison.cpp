#include "core/fleet/parametercomparison.h"

#include "core/params/parameterdictionary.h"

#include <QSet>

namespace dd {

Error ParameterComparison::checkFamilies(const QList<ParameterSource> &sources)
{
    for (const ParameterSource &s : sources) {
        if (s.family != sources.first().family) {
            return {ErrorCode::InvalidArgument,
                    tr("%1 is of a %2 drive and %3 of a %4 drive: parameters of different families have "
                       "different meanings and are never compared.")
                        .arg(sources.first().label, familyId(sources.first().family), s.label, familyId(s.family))};
        }
    }
    return {};
}

ParameterComparison ParameterComparison::compute(const ParameterDictionary &dictionary,
                                                 const QList<ParameterSource> &sources)
{
    ParameterComparison c;
    c.m_sources = sources;
    for (const ParameterInfo &p : dictionary.parameters()) {
        Row row;
        row.index = p.index;
        row.key = p.key;
        row.communication = p.communication;
        std::optional<qint64> first;
        bool any = false;
        for (const ParameterSource &s : sources) {
            const std::optional<qint64> v = s.values.value(p.index);
            row.values.append(v);
            if (!v) {
                row.missing = true;
                continue;
            }
            any = true;
            if (!first)
                first = v;
            else if (*first != *v)
                row.differs = true;
        }
        if (any)
            c.m_rows.append(row);
    }
    return c;
}

int ParameterComparison::differenceCount() const
{
    int n = 0;
    for (const Row &r : m_rows)
        n += r.differs ? 1 : 0;
    return n;
}

bool ParameterComparison::firmwareDiffers() const
{
    QSet<QString> seen;
    for (const ParameterSource &s : m_sources)
        if (!s.firmware.isEmpty())
            seen.insert(s.firmware);
    return seen.size() > 1;
}

} // namespace dd
