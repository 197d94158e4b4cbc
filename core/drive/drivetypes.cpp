#include "core/drive/drivetypes.h"

#include "core/protocol/servomodbus/servomodbus.h"

#include <QCoreApplication>

namespace dd {

QStringList channelUnits()
{
    static const char *const units[] = {
        QT_TRANSLATE_NOOP("dd::ChannelUnit", "r/min"),
        QT_TRANSLATE_NOOP("dd::ChannelUnit", "pulse"),
        QT_TRANSLATE_NOOP("dd::ChannelUnit", "pulses"),
        QT_TRANSLATE_NOOP("dd::ChannelUnit", "pulse/s"),
        QT_TRANSLATE_NOOP("dd::ChannelUnit", "%"),
        QT_TRANSLATE_NOOP("dd::ChannelUnit", "A"),
        QT_TRANSLATE_NOOP("dd::ChannelUnit", "V"),
        QT_TRANSLATE_NOOP("dd::ChannelUnit", "°C"),
        QT_TRANSLATE_NOOP("dd::ChannelUnit", "kHz"),
        QT_TRANSLATE_NOOP("dd::ChannelUnit", "Hz"),
        // Units of the bundled parameter dictionaries (resources/dictionaries).
        QT_TRANSLATE_NOOP("dd::ChannelUnit", "pulse/s²"),
        QT_TRANSLATE_NOOP("dd::ChannelUnit", "1/s"),
        QT_TRANSLATE_NOOP("dd::ChannelUnit", "r/min/ms"),
    };
    QStringList out;
    for (const char *u : units)
        out << QString::fromUtf8(u);
    return out;
}

QString channelUnitText(const QString &unit)
{
    if (unit.isEmpty())
        return unit;
    const QByteArray utf8 = unit.toUtf8();
    return QCoreApplication::translate("dd::ChannelUnit", utf8.constData());
}

QString capabilityId(Capability c)
{
    switch (c) {
    case Capability::ReadParameters: return QStringLiteral("read-parameters");
    case Capability::WriteParameters: return QStringLiteral("write-parameters");
    case Capability::Monitor: return QStringLiteral("monitor");
    case Capability::Jog: return QStringLiteral("jog");
    case Capability::MoveRelative: return QStringLiteral("move-relative");
    case Capability::MoveAbsolute: return QStringLiteral("move-absolute");
    case Capability::Home: return QStringLiteral("home");
    case Capability::Enable: return QStringLiteral("enable");
    case Capability::Stop: return QStringLiteral("stop");
    case Capability::EmergencyStop: return QStringLiteral("emergency-stop");
    case Capability::ReadAlarm: return QStringLiteral("read-alarm");
    case Capability::ClearAlarm: return QStringLiteral("clear-alarm");
    case Capability::EeOperations: return QStringLiteral("ee-operations");
    case Capability::SetPosition: return QStringLiteral("set-position");
    }
    return {};
}

QString stoppedById(JogEnd::StoppedBy by)
{
    switch (by) {
    case JogEnd::StoppedBy::Command: return QStringLiteral("command");
    case JogEnd::StoppedBy::DriveWatchdog: return QStringLiteral("drive-watchdog");
    case JogEnd::StoppedBy::Nothing: return QStringLiteral("nothing");
    }
    return {};
}

QStringList capabilityIds(Capabilities caps)
{
    QStringList out;
    for (quint32 bit = 1; bit != 0 && bit <= (1u << 13); bit <<= 1) {
        if (caps.testFlag(static_cast<Capability>(bit)))
            out << capabilityId(static_cast<Capability>(bit));
    }
    return out;
}

// The servo-modbus register map owns the EE operation table; the Drive API's
// family-neutral enum uses the same op codes.
static servomodbus::EeOp toEeOp(EeOperation op)
{
    return static_cast<servomodbus::EeOp>(static_cast<quint16>(op));
}

QString eeMnemonic(EeOperation op)
{
    return QString::fromLatin1(servomodbus::eeOpMnemonic(toEeOp(op)));
}

QString eeMeaning(EeOperation op)
{
    return QCoreApplication::translate(servomodbus::TranslationContext, servomodbus::eeOpMeaning(toEeOp(op)));
}

bool eeIsDestructive(EeOperation op)
{
    return servomodbus::eeOpNeedsConfirmation(toEeOp(op));
}

std::optional<EeOperation> eeFromText(const QString &text)
{
    QString t = text.trimmed().toLower();
    if (t.startsWith(QLatin1String("ee-")))
        t = t.mid(3);
    static const struct
    {
        const char *name;
        EeOperation op;
    } names[] = {
        {"set", EeOperation::Save},          {"1", EeOperation::Save},          {"rd", EeOperation::Reload},
        {"2", EeOperation::Reload},          {"ba", EeOperation::Backup},       {"3", EeOperation::Backup},
        {"rs", EeOperation::RestoreBackup},  {"4", EeOperation::RestoreBackup}, {"def", EeOperation::FactoryDefaults},
        {"5", EeOperation::FactoryDefaults},
    };
    for (const auto &n : names)
        if (t == QLatin1String(n.name))
            return n.op;
    return std::nullopt;
}

} // namespace dd
