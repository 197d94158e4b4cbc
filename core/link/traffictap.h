#pragma once

#include "core/link/trafficrecord.h"
#include "core/protocol/canframedata.h"

#include <QElapsedTimer>
#include <QObject>
#include <atomic>

namespace dd {

// Every frame a link sends or receives passes through its tap (if it has one). The frame
// monitor, --trace and tests listen to frameRecorded(). Cheap when nobody listens.
// Counters are atomic so another thread may read them.
class TrafficTap : public QObject
{
    Q_OBJECT
public:
    explicit TrafficTap(QObject *parent = nullptr);

    void recordSerial(TrafficRecord::Direction dir, const QString &link, const QByteArray &bytes,
                      const QString &note = {});
    void recordCan(TrafficRecord::Direction dir, const QString &link, const CanFrameData &frame,
                   const QString &note = {});
    void record(TrafficRecord record);

    quint64 txCount() const { return m_tx.load(); }
    quint64 rxCount() const { return m_rx.load(); }
    quint64 discardedCount() const { return m_discarded.load(); }

signals:
    void frameRecorded(const dd::TrafficRecord &record);

private:
    QElapsedTimer m_clock;
    std::atomic<quint64> m_tx{0};
    std::atomic<quint64> m_rx{0};
    std::atomic<quint64> m_discarded{0};
};

} // namespace dd
