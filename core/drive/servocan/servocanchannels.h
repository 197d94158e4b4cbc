#pragma once

#include "core/drive/drivetypes.h"
#include "core/protocol/servocan/servocan.h"

#include <QList>
#include <QString>
#include <optional>

// The live values of a `servo-can` drive: the 0x12 read types other than parameters, under
// the channel ids shared by all families ("speed", "current", "inputs", ...).
namespace dd::servocanchannels {

struct Channel
{
    const char *id;          // stable channel id
    servocan::ReadType type; // the 0x12 read that gives it
};

const QList<Channel> &all();
// The channel of `id`; the codec's read-type keys ("output-current", "input-io", ...) are
// accepted as aliases.
std::optional<Channel> find(const QString &id);
ChannelInfo info(const Channel &channel); // translated name, unit, decimals
QList<ChannelInfo> infos();

} // namespace dd::servocanchannels
