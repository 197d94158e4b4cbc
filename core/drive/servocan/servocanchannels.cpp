#include "core/drive/servocan/servocanchannels.h"

#include <QCoreApplication>

namespace dd::servocanchannels {

using servocan::ReadType;

const QList<Channel> &all()
{
    static const QList<Channel> channels = {
        {"speed", ReadType::Speed},
        {"position", ReadType::Position},
        {"position-command", ReadType::PositionCommand},
        {"position-error", ReadType::PositionError},
        {"torque", ReadType::Torque},
        {"current", ReadType::OutputCurrent},
        {"speed-command", ReadType::SpeedCommand},
        {"torque-command", ReadType::TorqueCommand},
        {"rotor-position", ReadType::RotorPosition},
        {"bus-voltage", ReadType::BusVoltage},
        {"temperature", ReadType::Temperature},
        {"inputs", ReadType::InputIo},
        {"outputs", ReadType::OutputIo},
        {"alarm", ReadType::AlarmCode},
    };
    return channels;
}

std::optional<Channel> find(const QString &id)
{
    for (const Channel &c : all()) {
        if (id == QLatin1String(c.id) || id == QLatin1String(servocan::readTypeInfo(c.type).key))
            return c;
    }
    return std::nullopt;
}

ChannelInfo info(const Channel &channel)
{
    const servocan::ReadTypeInfo t = servocan::readTypeInfo(channel.type);
    ChannelInfo i;
    i.id = QString::fromLatin1(channel.id);
    i.name = QCoreApplication::translate("dd::servocan", t.name);
    i.unit = QString::fromUtf8(t.unit); // untranslated: the display translates it (channelUnits())
    i.decimals = t.decimals;
    return i;
}

QList<ChannelInfo> infos()
{
    QList<ChannelInfo> out;
    for (const Channel &c : all())
        out.append(info(c));
    return out;
}

} // namespace dd::servocanchannels
