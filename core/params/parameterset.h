#pragma once

#include <QList>
#include <QMap>
#include <optional>

namespace dd {

// Where a value in a ParameterSet came from.
enum class ValueSource {
    Unknown,       // the parameter exists but its value is not known (read failed, never written)
    ReadFromDrive, // read back from the drive
    LastWritten    // write-only parameter: the value DriveDesk last wrote (the drive cannot report it)
};

struct ParameterValue
{
    qint64 value = 0;
    ValueSource source = ValueSource::Unknown;

    bool isKnown() const { return source != ValueSource::Unknown; }
    friend bool operator==(const ParameterValue &a, const ParameterValue &b)
    {
        return a.source == b.source && (a.source == ValueSource::Unknown || a.value == b.value);
    }
    friend bool operator!=(const ParameterValue &a, const ParameterValue &b) { return !(a == b); }
};

// Values of a drive's parameters keyed by dictionary index (ascending).
class ParameterSet
{
public:
    void set(int index, qint64 value, ValueSource source = ValueSource::ReadFromDrive);
    void setUnknown(int index);
    void remove(int index) { m_values.remove(index); }
    void clear() { m_values.clear(); }

    bool contains(int index) const { return m_values.contains(index); }
    bool isKnown(int index) const;
    ParameterValue entry(int index) const;        // source Unknown when absent
    std::optional<qint64> value(int index) const; // nullopt when absent or unknown
    QList<int> indices() const { return m_values.keys(); }
    QList<int> knownIndices() const;
    int size() const { return m_values.size(); }
    bool isEmpty() const { return m_values.isEmpty(); }
    const QMap<int, ParameterValue> &entries() const { return m_values; }

    friend bool operator==(const ParameterSet &a, const ParameterSet &b) { return a.m_values == b.m_values; }
    friend bool operator!=(const ParameterSet &a, const ParameterSet &b) { return !(a == b); }

private:
    QMap<int, ParameterValue> m_values;
};

} // namespace dd
