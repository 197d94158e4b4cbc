#include "core/link/traffictap.h"

#include <QDateTime>

namespace dd {

TrafficTap::TrafficTap(QObject *parent)
    : QObject(parent)
{
    qRegisterMetaType<dd::TrafficRecord>();
    m_clock.start();
}

void TrafficTap::recordSerial(TrafficRecord::Direction dir, const QString &link, const QByteArray &bytes,
                              const QString &note)
{
    TrafficRecord r;
    r.direction = dir;
    r.link = link;
    r.bytes = bytes;
    r.note = note;
    record(std::move(r));
}

void TrafficTap::recordCan(TrafficRecord::Direction dir, const QString &link, const CanFrameData &frame,
                           const QString &note)
{
    TrafficRecord r;
    r.direction = dir;
    r.link = link;
    r.bytes = frame.data;
    r.isCan = true;
    r.canId = frame.id;
    r.canExtended = frame.extended;
    r.note = note;
    record(std::move(r));
}

void TrafficTap::record(TrafficRecord record)
{
    record.timestampUs = m_clock.nsecsElapsed() / 1000;
    record.wallclockMs = QDateTime::currentMSecsSinceEpoch();
    switch (record.direction) {
    case TrafficRecord::Direction::Tx: ++m_tx; break;
    case TrafficRecord::Direction::Rx: ++m_rx; break;
    case TrafficRecord::Direction::Discarded: ++m_discarded; break;
    }
    emit frameRecorded(record);
}

} // namespace dd
