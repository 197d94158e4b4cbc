#pragma once

#include "core/params/localizedtext.h"

#include <QString>
#include <QStringList>
#include <optional>

namespace dd {

// Whether a parameter can be read from and written to the drive.
enum class Access { ReadWrite, ReadOnly, WriteOnly };

// How a parameter's value travels on the wire; bounds min/max of a dictionary entry.
enum class ValueType { UInt8, Int16, UInt16, Int32, UInt32 };

QString accessId(Access access);                       // "rw", "ro", "wo"
std::optional<Access> accessFromId(const QString &id); // exact, lower case
QString valueTypeId(ValueType type);                   // "uint8", "int16", ...
std::optional<ValueType> valueTypeFromId(const QString &id);
qint64 valueTypeMin(ValueType type);
qint64 valueTypeMax(ValueType type);

// One entry of a parameter dictionary (see docs/dictionaries.md).
struct ParameterInfo
{
    int index = -1; // servo-can 0..219, servo-modbus PA number, shuoke SET command code
    QString key;    // stable identifier: "P4", "PA12", "start-speed"
    LocalizedText name;
    LocalizedText description;
    QString unit; // "" when dimensionless
    ValueType type = ValueType::Int16;
    qint64 min = 0;
    qint64 max = 0;
    std::optional<qint64> defaultValue;
    Access access = Access::ReadWrite;
    int readCommand = -1;       // shuoke: GET command code; -1 = none
    int registerAddress = -1;   // servo-modbus: holding register; -1 = none
    bool communication = false; // changes how the drive talks (address, baud, framing)
    QStringList models;         // drive models it applies to; empty = all

    bool isReadable() const { return access != Access::WriteOnly; }
    bool isWritable() const { return access != Access::ReadOnly; }
    bool inRange(qint64 value) const { return value >= min && value <= max; }
    QString displayName(const QLocale &locale = QLocale()) const { return name.text(locale); }
};

} // namespace dd
