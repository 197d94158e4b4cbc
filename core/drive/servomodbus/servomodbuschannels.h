#pragma once

#include "core/drive/drivetypes.h"
#include "core/protocol/servomodbus/servomodbus.h"

#include <QHash>
#include <QList>
#include <QStringList>

namespace dd {

// The live values of a servo-modbus drive: one channel per DP monitor register (0x00..0x16;
// DP-rES is left out), the three position pairs also combined by the position rule
// ("position", "position-command", "position-error") next to their raw halves
// ("position-low", "position-high", ...). Units are this drive class's usual ones (the seed
// gives none): r/min, % of rated torque, 0.01 A per count for the currents, encoder counts.
// Registers without a known meaning (DP-LSP, DP-Cnt, DP-m, DP-tL) are raw values.
class ServoModbusChannels
{
public:
    static QList<ChannelInfo> channels(); // translated names
    static QStringList ids();
    // The registers a channel needs (1, or 2 for a combined pair); empty when unknown.
    static QList<quint16> registers(const QString &channelId);
    // The channel's value from register values (all of registers(channelId) present).
    static double value(const QString &channelId, const QHash<quint16, quint16> &registers,
                        servomodbus::PositionPairRule rule);
};

} // namespace dd
