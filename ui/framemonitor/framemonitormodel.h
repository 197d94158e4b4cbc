#pragma once

#include "core/link/connectionsettings.h"
#include "core/link/trafficlog.h"
#include "core/link/trafficrecord.h"

#include <QAbstractTableModel>
#include <QHash>
#include <QPointer>
#include <QStringList>
#include <QTimer>
#include <deque>
#include <memory>

namespace dd {

class DriveHub;
class FrameDescriber;

// The frame monitor's rows: every frame of every link of a DriveHub, with its decoded
// meaning (FrameDescriber, one per connection, fed in arrival order), in a bounded ring
// (capacity() rows; the oldest go first).
//
// Frames arrive one by one (1000+ per second on a busy CAN bus) but are inserted in
// batches: they are described and queued at once, and a timer inserts the queue every
// FlushIntervalMs with one beginInsertRows — the view is never updated per frame.
//
// Pause: the view holds still, but recording goes on — frames received while paused are
// kept (up to capacity()) and appear when the pause ends, so that nothing is missed while
// the user reads. clear() drops the rows and the held frames.
class FrameMonitorModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column { TimeColumn, LinkColumn, DirectionColumn, DataColumn, MeaningColumn, ColumnCount };
    enum Role { DirectionRole = Qt::UserRole + 1, ConnectionRole };
    static constexpr int DefaultCapacity = 50000;
    static constexpr int FlushIntervalMs = 100;

    struct Row
    {
        int connectionId = 0;
        TrafficRecord record;
        QString meaning;
    };

    explicit FrameMonitorModel(QObject *parent = nullptr);
    ~FrameMonitorModel() override;

    // Records the hub's traffic (trafficRecorded); the link's family comes from the hub's
    // connection settings.
    void setHub(DriveHub *hub);
    // How to describe the frames of a connection (without a hub, or to override it).
    void describeConnection(int connectionId, const ConnectionSettings &settings);

    void setCapacity(int rows);
    int capacity() const { return m_capacity; }

    // Describes and queues one frame; it is inserted at the next flush.
    void addRecord(int connectionId, const TrafficRecord &record);
    // Inserts the queued frames now (unless paused).
    void flush();
    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    int heldCount() const { return int(m_pending.size()); }
    // Frames pushed out of the ring (or of the held queue) since the last clear().
    quint64 droppedCount() const { return m_dropped; }
    void clear();

    const Row &row(int index) const { return m_rows.at(size_t(index)); }
    TrafficLog::Entry entry(int index) const;
    QStringList links() const { return m_links; } // link names seen, in order of appearance

    // QAbstractItemModel
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

    // Re-reads the header texts (call on QEvent::LanguageChange).
    void retranslate();

signals:
    void linksChanged();
    // After each flush, after clear() and when the held count changes.
    void countsChanged();

private:
    FrameDescriber *describerFor(int connectionId);

    QPointer<DriveHub> m_hub;
    std::deque<Row> m_rows;
    std::deque<Row> m_pending;
    QHash<int, std::shared_ptr<FrameDescriber>> m_describers;
    QStringList m_links;
    QTimer m_flushTimer;
    int m_capacity = DefaultCapacity;
    quint64 m_dropped = 0;
    bool m_paused = false;
};

} // namespace dd
