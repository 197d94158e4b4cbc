#include "core/params/parameterinfo.h"

#include <limits>

namespace dd {

QString accessId(Access access)
{
    switch (access) {
    case Access::ReadWrite: return QStringLiteral("rw");
    case Access::ReadOnly: return QStringLiteral("ro");
    case Access::WriteOnly: return QStringLiteral("wo");
    }
    return {};
}

std::optional<Access> accessFromId(const QString &id)
{
    for (Access a : {Access::ReadWrite, Access::ReadOnly, Access::WriteOnly}) {
        if (accessId(a) == id)
            return a;
    }
    return std::nullopt;
}

static const ValueType allValueTypes[] = {ValueType::UInt8, ValueType::Int16, ValueType::UInt16, ValueType::Int32,
                                          ValueType::UInt32};

QString valueTypeId(ValueType type)
{
    switch (type) {
    case ValueType::UInt8: return QStringLiteral("uint8");
    case ValueType::Int16: return QStringLiteral("int16");
    case ValueType::UInt16: return QStringLiteral("uint16");
    case ValueType::Int32: return QStringLiteral("int32");
    case ValueType::UInt32: return QStringLiteral("uint32");
    }
    return {};
}

std::optional<ValueType> valueTypeFromId(const QString &id)
{
    for (ValueType t : allValueTypes) {
        if (valueTypeId(t) == id)
            return t;
    }
    return std::nullopt;
}

qint64 valueTypeMin(ValueType type)
{
    switch (type) {
    case ValueType::Int16: return std::numeric_limits<qint16>::min();
    case ValueType::Int32: return std::numeric_limits<qint32>::min();
    case ValueType::UInt8:
    case ValueType::UInt16:
    case ValueType::UInt32: return 0;
    }
    return 0;
}

qint64 valueTypeMax(ValueType type)
{
    switch (type) {
    case ValueType::UInt8: return std::numeric_limits<quint8>::max();
    case ValueType::Int16: return std::numeric_limits<qint16>::max();
    case ValueType::UInt16: return std::numeric_limits<quint16>::max();
    case ValueType::Int32: return std::numeric_limits<qint32>::max();
    case ValueType::UInt32: return std::numeric_limits<quint32>::max();
    }
    return 0;
}

} // namespace dd
