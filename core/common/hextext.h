#pragma once

#include <QString>

namespace dd {

// "0x1a", "0x0006": a byte or register number as the protocol notes and error messages write
// it, lower-case with leading zeros up to `digits`.
inline QString hexText(quint32 value, int digits)
{
    return QStringLiteral("0x%1").arg(value, digits, 16, QLatin1Char('0'));
}

} // namespace dd
