#pragma once

#include <QString>
#include <optional>

namespace dd {

// One parameter of a drive in a commissioning record: its value on the drive next to the
// dictionary's default.
struct RecordParameter
{
    int index = 0;
    QString key;  // "PA5", "P30", "start-speed"
    QString name; // in the record's language
    QString unit;
    std::optional<qint64> value;        // none: not read (write-only, or the read failed)
    std::optional<qint64> defaultValue; // none: the dictionary gives no default

    // Known on the drive, with a known default, and different from it.
    bool differsFromDefault() const { return value && defaultValue && *value != *defaultValue; }
};

} // namespace dd
