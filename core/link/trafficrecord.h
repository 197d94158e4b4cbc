#pragma once

#include <QByteArray>
#include <QMetaType>
#include <QString>
#include <QtGlobal>

namespace dd {

// One frame on a link, as the frame monitor and --trace show it.
struct TrafficRecord
{
    enum class Direction { Tx, Rx, Discarded };

    qint64 timestampUs = 0; // microseconds since the tap was created (monotonic)
    qint64 wallclockMs = 0; // milliseconds since the epoch, for files and display
    Direction direction = Direction::Tx;
    QString link;     // e.g. "/dev/ttyUSB0", "virtualcan:can0"
    QByteArray bytes; // serial: the frame bytes; CAN: the data field
    bool isCan = false;
    quint32 canId = 0;
    bool canExtended = false;
    QString note; // optional: "late reply", "retry 2", decoded meaning, ...

    QString directionText() const; // "TX", "RX", "DROP"
    QString hexText() const;       // "01 03 00 64 00 14 C4 1A" (CAN: "065#00 12 ...")
};

} // namespace dd

Q_DECLARE_METATYPE(dd::TrafficRecord)
