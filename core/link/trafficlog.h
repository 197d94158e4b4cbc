#pragma once

#include "core/common/error.h"
#include "core/link/trafficrecord.h"

#include <QCoreApplication>
#include <QList>

namespace dd {

// Saved link traffic (the frame monitor's Save, traces): one line per frame with its time,
// link, direction, bytes and decoded meaning. Two formats, chosen by the file name:
//   - CSV (".csv"): UTF-8, LF, comma separator, fields quoted as csvField() does (core/common/csvfield.h);
//     header `time,time_us,link,direction,can_id,data,meaning,note`. `time` is the wall
//     clock in ISO 8601 with milliseconds and the UTC offset; `time_us` the link tap's
//     monotonic microseconds; `can_id` hex ("065", 8 digits when extended), empty for serial;
//     `data` the bytes in hex separated by spaces; direction TX / RX / DROP.
//   - text (anything else): the same fields separated by two spaces, local time
//     "yyyy-MM-dd HH:mm:ss.zzz", CAN frames as "065#00 12 ..", the note in brackets.
// Files are written atomically (QSaveFile): complete or not at all.
class TrafficLog
{
    Q_DECLARE_TR_FUNCTIONS(dd::TrafficLog)

public:
    enum class Format { Text, Csv };

    struct Entry
    {
        TrafficRecord record;
        QString meaning;
    };

    static Format formatForPath(const QString &path); // ".csv" (any case) → Csv
    static QByteArray csvHeader();
    static QByteArray csvLine(const Entry &entry);
    static QByteArray textLine(const Entry &entry);
    static QByteArray toBytes(const QList<Entry> &entries, Format format);
    static Error save(const QString &path, const QList<Entry> &entries);
};

} // namespace dd
