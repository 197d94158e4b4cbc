#pragma once

#include "core/protocol/shuoke/shuokecommands.h"
#include "core/protocol/shuoke/shuokevalues.h"

#include <QByteArray>
#include <QList>
#include <optional>

namespace dd {

// One setting of a Shuoke drive as a parameter (docs/protocols/shuoke.md,
// "Parameters"). The parameter index is the code of its SET command, as in the bundled
// dictionary (resources/dictionaries/shuoke.json); readCommand is its GET command, 0 for
// the write-only settings, which no command reads back.
struct ShuokeParameter
{
    quint8 setCommand = 0;  // = parameter index
    quint8 readCommand = 0; // 0: write-only
    int size = 4;           // data bytes of the SET request and GET reply: 1 or 4
    qint64 min = 0;
    qint64 max = 0;
    const char *key = nullptr; // dictionary key, e.g. "start-speed"

    int index() const { return setCommand; }
    bool isReadable() const { return readCommand != 0; }
    bool inRange(qint64 v) const { return v >= min && v <= max; }
    bool isSupportedBy(shuoke::Model model) const { return shuoke::isSupportedBy(setCommand, model, size); }

    QByteArray encode(qint64 value, shuoke::ByteOrder order) const;
    std::optional<qint64> decode(const QByteArray &data, shuoke::ByteOrder order) const;

    // The whole set, readable ones first (by index), then the write-only ones.
    static const QList<ShuokeParameter> &all();
    static const ShuokeParameter *byIndex(int index);
};

} // namespace dd
