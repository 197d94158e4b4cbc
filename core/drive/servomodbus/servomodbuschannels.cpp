#include "core/drive/servomodbus/servomodbuschannels.h"

#include <QCoreApplication>

namespace dd {

namespace {

enum class Kind { Signed, Unsigned, Pair, Centi };

struct ModbusChannelDef
{
    const char *id;
    const char *name; // QT_TRANSLATE_NOOP in "dd::ServoModbusDrive"
    const char *unit;
    int decimals;
    quint16 reg;
    Kind kind;
};

// Units are this drive class's usual ones (the seed gives none): r/min, % of rated torque,
// 0.01 A per count for the currents, encoder counts for positions.
const QList<ModbusChannelDef> &channelDefs()
{
    static const QList<ModbusChannelDef> defs = {
        {"speed", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Speed (DP-SPd)"), "r/min", 0, 0x00, Kind::Signed},
        {"position", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Position (DP-PoS)"), "pulse", 0, 0x01, Kind::Pair},
        {"position-low", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Position, low register (DP-PoS)"), "", 0, 0x01,
         Kind::Unsigned},
        {"position-high", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Position, high register (DP-PoS.)"), "", 0, 0x02,
         Kind::Signed},
        {"position-command", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Command position (DP-CPo)"), "pulse", 0, 0x03,
         Kind::Pair},
        {"position-command-low", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Command position, low register (DP-CPo)"),
         "", 0, 0x03, Kind::Unsigned},
        {"position-command-high",
         QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Command position, high register (DP-CPo.)"), "", 0, 0x04,
         Kind::Signed},
        {"position-error", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Position error (DP-EPo)"), "pulse", 0, 0x05,
         Kind::Pair},
        {"position-error-low", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Position error, low register (DP-EPo)"), "",
         0, 0x05, Kind::Unsigned},
        {"position-error-high", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Position error, high register (DP-EPo.)"),
         "", 0, 0x06, Kind::Signed},
        {"torque", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Torque (DP-trq)"), "%", 0, 0x07, Kind::Signed},
        {"current", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Current (DP-I)"), "A", 2, 0x08, Kind::Centi},
        {"dp-lsp", "DP-LSP", "", 0, 0x09, Kind::Signed},
        {"dp-cnt", "DP-Cnt", "", 0, 0x0A, Kind::Signed},
        {"pulse-frequency", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Pulse frequency (DP-Frq)"), "kHz", 0, 0x0B,
         Kind::Signed},
        {"speed-command", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Speed command (DP-CS)"), "r/min", 0, 0x0C,
         Kind::Signed},
        {"torque-command", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Torque command (DP-Ct)"), "%", 0, 0x0D,
         Kind::Signed},
        {"rotor-position", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Rotor absolute position (DP-APo)"), "pulse", 0,
         0x0E, Kind::Unsigned},
        {"inputs", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Input terminals (DP-In)"), "", 0, 0x0F, Kind::Unsigned},
        {"outputs", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Output terminals (DP-oUt)"), "", 0, 0x10,
         Kind::Unsigned},
        {"encoder-signals", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Encoder signals (DP-Cod)"), "", 0, 0x11,
         Kind::Unsigned},
        {"dp-m", "DP-m", "", 0, 0x12, Kind::Signed},
        {"alarm", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Alarm (DP-Err)"), "", 0, 0x13, Kind::Unsigned},
        {"dp-tl", "DP-tL", "", 0, 0x14, Kind::Signed},
        {"phase-a-current", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Phase A current (DP-IA)"), "A", 2, 0x15,
         Kind::Centi},
        {"phase-c-current", QT_TRANSLATE_NOOP("dd::ServoModbusDrive", "Phase C current (DP-IC)"), "A", 2, 0x16,
         Kind::Centi},
    };
    return defs;
}

const ModbusChannelDef *modbusChannelDef(const QString &id)
{
    for (const ModbusChannelDef &d : channelDefs())
        if (id == QLatin1String(d.id))
            return &d;
    return nullptr;
}

} // namespace

QList<ChannelInfo> ServoModbusChannels::channels()
{
    QList<ChannelInfo> out;
    for (const ModbusChannelDef &d : channelDefs())
        out.append({QLatin1String(d.id), QCoreApplication::translate("dd::ServoModbusDrive", d.name),
                    QString::fromUtf8(d.unit), d.decimals});
    return out;
}

QStringList ServoModbusChannels::ids()
{
    QStringList out;
    for (const ModbusChannelDef &d : channelDefs())
        out << QLatin1String(d.id);
    return out;
}

QList<quint16> ServoModbusChannels::registers(const QString &channelId)
{
    const ModbusChannelDef *d = modbusChannelDef(channelId);
    if (!d)
        return {};
    if (d->kind == Kind::Pair)
        return {d->reg, static_cast<quint16>(d->reg + 1)};
    return {d->reg};
}

double ServoModbusChannels::value(const QString &channelId, const QHash<quint16, quint16> &registers,
                                  servomodbus::PositionPairRule rule)
{
    const ModbusChannelDef *d = modbusChannelDef(channelId);
    if (!d)
        return 0.0;
    const quint16 v = registers.value(d->reg);
    switch (d->kind) {
    case Kind::Signed: return double(qint16(v));
    case Kind::Unsigned: return double(v);
    case Kind::Centi: return double(qint16(v)) / 100.0;
    case Kind::Pair: return double(servomodbus::combinePositionPair(v, registers.value(quint16(d->reg + 1)), rule));
    }
    return 0.0;
}

} // namespace dd
