#include "core/protocol/servocan/servocandescriber.h"

#include "core/protocol/servocan/servocan.h"

namespace dd {

QString ServoCanDescriber::describeCan(Origin origin, const CanFrameData &frame)
{
    using namespace servocan;
    const Decoded<Message> d = decode(frame);
    if (!d.ok())
        return failed(d.error);
    const Message &m = *d.value;
    QString text;
    switch (m.command) {
    case Command::Alarm: text = m.alarmCode() ? tr("alarm %1").arg(m.alarmCode()) : tr("no alarm"); break;
    case Command::KeepAlive: text = tr("keep-alive"); break;
    case Command::Heartbeat:
        text = m.heartbeatIdle() ? tr("heartbeat: idle, position %1").arg(m.value)
                                 : tr("heartbeat: running, position %1").arg(m.value);
        break;
    case Command::Read: {
        const ReadType type = m.readType().value_or(ReadType::Parameter);
        if (type == ReadType::Parameter) {
            text = origin == Origin::Host ? tr("read P%1").arg(m.paramIndex)
                                          : tr("P%1 = %2").arg(m.paramIndex).arg(m.paramValue);
            break;
        }
        const ReadTypeInfo info = readTypeInfo(type);
        const QString name = QCoreApplication::translate("dd::servocan", info.name);
        if (origin == Origin::Host) {
            text = tr("read %1").arg(name);
            break;
        }
        QString value;
        if (info.bitField)
            value = QStringLiteral("0x") + QString::number(quint32(m.value), 16).toUpper();
        else
            value = QString::number(scaledValue(type, m.value), 'f', info.decimals);
        if (info.unit && *info.unit)
            value += QLatin1Char(' ') + QCoreApplication::translate("dd::servocan", info.unit);
        text = tr("%1 = %2").arg(name, value);
        break;
    }
    case Command::Write: text = tr("write P%1 = %2").arg(m.paramIndex).arg(m.paramValue); break;
    case Command::RunSpeed: text = m.value ? tr("run at %1 r/min").arg(m.value) : tr("run at 0 r/min (halt)"); break;
    case Command::MoveRelative: text = tr("move by %1").arg(m.value); break;
    case Command::MoveAbsolute: text = tr("move to %1").arg(m.value); break;
    case Command::PositioningSpeed: text = tr("positioning speed %1 r/min").arg(m.value); break;
    case Command::Enable: text = m.enableOn() ? tr("servo on") : tr("servo off"); break;
    case Command::Stop: text = tr("stop"); break;
    case Command::StopAndDisable: text = tr("stop and disable"); break;
    case Command::SetPosition: text = tr("set position to %1").arg(m.value); break;
    case Command::ClearAlarm: text = tr("clear alarm"); break;
    }
    return station(m.station) + text;
}

} // namespace dd
