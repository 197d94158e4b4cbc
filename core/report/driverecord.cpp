#include "core/report/driverecord.h"

#include "core/params/parameterdictionary.h"

namespace dd {

QList<RecordParameter> DriveRecord::nonDefault() const
{
    QList<RecordParameter> list;
    for (const RecordParameter &p : parameters)
        if (p.differsFromDefault())
            list.append(p);
    return list;
}

int DriveRecord::withoutDefault() const
{
    int n = 0;
    for (const RecordParameter &p : parameters)
        if (p.value && !p.defaultValue)
            ++n;
    return n;
}

void DriveRecord::setParameters(const ParameterDictionary &dictionary, const QMap<int, qint64> &values,
                                const QLocale &locale)
{
    parameters.clear();
    parameters.reserve(dictionary.size());
    for (const ParameterInfo &info : dictionary.parameters()) {
        RecordParameter p;
        p.index = info.index;
        p.key = info.key;
        p.name = info.displayName(locale);
        p.unit = info.unit;
        p.defaultValue = info.defaultValue;
        const auto it = values.constFind(info.index);
        if (it != values.constEnd())
            p.value = *it;
        parameters.append(p);
    }
}

} // namespace dd
