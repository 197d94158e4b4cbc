#include "core/link/trafficrecord.h"

namespace dd {

QString TrafficRecord::directionText() const
{
    switch (direction) {
    case Direction::Tx: return QStringLiteral("TX");
    case Direction::Rx: return QStringLiteral("RX");
    case Direction::Discarded: return QStringLiteral("DROP");
    }
    return {};
}

QString TrafficRecord::hexText() const
{
    const QString hex = QString::fromLatin1(bytes.toHex(' ').toUpper());
    if (!isCan)
        return hex;
    const int width = canExtended ? 8 : 3;
    return QStringLiteral("%1#%2").arg(canId, width, 16, QLatin1Char('0')).arg(hex).toUpper();
}

} // namespace dd
