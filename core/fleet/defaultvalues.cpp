#include "core/fleet/defaultvalues.h"

#include "core/params/parameterdictionary.h"

namespace dd {

ParameterSet DefaultValues::of(const ParameterDictionary &dictionary)
{
    ParameterSet out;
    for (const ParameterInfo &p : dictionary.parameters())
        if (p.defaultValue)
            out.set(p.index, *p.defaultValue,
                    p.access == Access::WriteOnly ? ValueSource::LastWritten : ValueSource::ReadFromDrive);
    return out;
}

ParameterSet DefaultValues::changedOnly(const ParameterDictionary &dictionary, const ParameterSet &values)
{
    ParameterSet out;
    for (auto it = values.entries().begin(); it != values.entries().end(); ++it) {
        const ParameterInfo *p = dictionary.byIndex(it.key());
        if (!p || !it->isKnown() || !p->isWritable())
            continue;
        if (p->defaultValue && *p->defaultValue == it->value)
            continue;
        out.set(it.key(), it->value, it->source);
    }
    return out;
}

ParameterSet DefaultValues::completed(const ParameterDictionary &dictionary, const ParameterSet &values)
{
    ParameterSet out = values;
    for (const ParameterInfo &p : dictionary.parameters())
        if (p.defaultValue && p.isWritable() && !out.isKnown(p.index))
            out.set(p.index, *p.defaultValue,
                    p.access == Access::WriteOnly ? ValueSource::LastWritten : ValueSource::ReadFromDrive);
    return out;
}

} // namespace dd
