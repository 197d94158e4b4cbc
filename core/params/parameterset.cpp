#include "core/params/parameterset.h"

namespace dd {

void ParameterSet::set(int index, qint64 value, ValueSource source)
{
    if (source == ValueSource::Unknown)
        value = 0;
    m_values.insert(index, ParameterValue{value, source});
}

void ParameterSet::setUnknown(int index)
{
    m_values.insert(index, ParameterValue{});
}

bool ParameterSet::isKnown(int index) const
{
    const auto it = m_values.constFind(index);
    return it != m_values.constEnd() && it->isKnown();
}

ParameterValue ParameterSet::entry(int index) const
{
    return m_values.value(index);
}

std::optional<qint64> ParameterSet::value(int index) const
{
    const auto it = m_values.constFind(index);
    if (it == m_values.constEnd() || !it->isKnown())
        return std::nullopt;
    return it->value;
}

QList<int> ParameterSet::knownIndices() const
{
    QList<int> out;
    for (auto it = m_values.constBegin(); it != m_values.constEnd(); ++it) {
        if (it->isKnown())
            out.append(it.key());
    }
    return out;
}

} // namespace dd
