#include "ui/framemonitor/framemonitormodel.h"

#include "core/drive/drivehub.h"
#include "core/protocol/familytraits.h"
#include "core/protocol/framedescriber.h"

#include <QBrush>
#include <QColor>
#include <QDateTime>
#include <QFontDatabase>

namespace dd {

FrameMonitorModel::FrameMonitorModel(QObject *parent)
    : QAbstractTableModel(parent)
{
    m_flushTimer.setSingleShot(true);
    m_flushTimer.setInterval(FlushIntervalMs);
    connect(&m_flushTimer, &QTimer::timeout, this, &FrameMonitorModel::flush);
}

FrameMonitorModel::~FrameMonitorModel() = default;

void FrameMonitorModel::setHub(DriveHub *hub)
{
    if (m_hub)
        disconnect(m_hub, nullptr, this, nullptr);
    m_hub = hub;
    if (hub)
        connect(hub, &DriveHub::trafficRecorded, this, &FrameMonitorModel::addRecord);
}

void FrameMonitorModel::setCapacity(int rows)
{
    m_capacity = qMax(1, rows);
    if (int(m_rows.size()) > m_capacity) {
        const int excess = int(m_rows.size()) - m_capacity;
        beginRemoveRows({}, 0, excess - 1);
        m_rows.erase(m_rows.begin(), m_rows.begin() + excess);
        endRemoveRows();
        m_dropped += quint64(excess);
    }
    while (int(m_pending.size()) > m_capacity) {
        m_pending.pop_front();
        ++m_dropped;
    }
}

void FrameMonitorModel::describeConnection(int connectionId, const ConnectionSettings &settings)
{
    m_describers.insert(
        connectionId,
        std::shared_ptr<FrameDescriber>(createFrameDescriber(settings.family, settings.framing, settings.options)));
}

FrameDescriber *FrameMonitorModel::describerFor(int connectionId)
{
    if (auto it = m_describers.constFind(connectionId); it != m_describers.cend())
        return it->get();
    // The settings reach the hub's side before the link's first frame does; a frame of an
    // unknown connection is not described (and no describer is cached for it).
    if (!m_hub || !m_hub->connectionIds().contains(connectionId))
        return nullptr;
    describeConnection(connectionId, m_hub->connectionSettings(connectionId));
    return m_describers.value(connectionId).get();
}

void FrameMonitorModel::addRecord(int connectionId, const TrafficRecord &record)
{
    Row row;
    row.connectionId = connectionId;
    row.record = record;
    if (record.direction == TrafficRecord::Direction::Discarded) {
        row.meaning = tr("discarded");
    } else if (FrameDescriber *d = describerFor(connectionId)) {
        const auto origin = record.direction == TrafficRecord::Direction::Tx ? FrameDescriber::Origin::Host
                                                                             : FrameDescriber::Origin::Drive;
        if (record.isCan) {
            CanFrameData f;
            f.id = record.canId;
            f.data = record.bytes;
            f.extended = record.canExtended;
            row.meaning = d->describeCan(origin, f);
        } else {
            row.meaning = d->describeSerial(origin, record.bytes);
        }
    } else {
        row.meaning = FrameDescriber::unknown();
    }
    if (!m_links.contains(record.link)) {
        m_links.append(record.link);
        emit linksChanged();
    }
    m_pending.push_back(std::move(row));
    if (int(m_pending.size()) > m_capacity) {
        m_pending.pop_front();
        ++m_dropped;
    }
    if (m_paused)
        emit countsChanged();
    else if (!m_flushTimer.isActive())
        m_flushTimer.start();
}

void FrameMonitorModel::flush()
{
    m_flushTimer.stop();
    if (m_paused || m_pending.empty())
        return;
    const int incoming = int(m_pending.size()); // <= capacity
    const int excess = int(m_rows.size()) + incoming - m_capacity;
    if (excess >= int(m_rows.size()) && !m_rows.empty()) {
        // Everything shown goes: one reset instead of a removal and an insertion.
        beginResetModel();
        m_dropped += quint64(m_rows.size());
        m_rows.clear();
        m_rows.swap(m_pending);
        endResetModel();
        emit countsChanged();
        return;
    }
    if (excess > 0) {
        beginRemoveRows({}, 0, excess - 1);
        m_rows.erase(m_rows.begin(), m_rows.begin() + excess);
        endRemoveRows();
        m_dropped += quint64(excess);
    }
    const int first = int(m_rows.size());
    beginInsertRows({}, first, first + incoming - 1);
    std::move(m_pending.begin(), m_pending.end(), std::back_inserter(m_rows));
    m_pending.clear();
    endInsertRows();
    emit countsChanged();
}

void FrameMonitorModel::setPaused(bool paused)
{
    if (m_paused == paused)
        return;
    m_paused = paused;
    if (!paused)
        flush();
    emit countsChanged();
}

void FrameMonitorModel::clear()
{
    beginResetModel();
    m_rows.clear();
    m_pending.clear();
    m_dropped = 0;
    endResetModel();
    emit countsChanged();
}

TrafficLog::Entry FrameMonitorModel::entry(int index) const
{
    const Row &r = row(index);
    return {r.record, r.meaning};
}

int FrameMonitorModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int FrameMonitorModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant FrameMonitorModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= int(m_rows.size()))
        return {};
    const Row &r = m_rows.at(size_t(index.row()));
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case TimeColumn:
            return QDateTime::fromMSecsSinceEpoch(r.record.wallclockMs).toString(QStringLiteral("HH:mm:ss.zzz"));
        case LinkColumn: return r.record.link;
        case DirectionColumn: return r.record.directionText();
        case DataColumn: return r.record.hexText();
        case MeaningColumn:
            // The link's note only when it adds something ("retry 2", "late reply"), not
            // when it repeats the meaning ("Query absolute position [Query absolute position]").
            if (r.record.note.isEmpty() || r.meaning.contains(r.record.note.trimmed(), Qt::CaseInsensitive))
                return r.meaning;
            return QStringLiteral("%1 [%2]").arg(r.meaning, r.record.note);
        }
        break;
    case Qt::ToolTipRole:
        if (index.column() == MeaningColumn || index.column() == DataColumn)
            return data(index, Qt::DisplayRole);
        if (index.column() == TimeColumn)
            return QDateTime::fromMSecsSinceEpoch(r.record.wallclockMs).toString(Qt::ISODateWithMs);
        break;
    case Qt::ForegroundRole:
        if (index.column() == DirectionColumn || index.column() == DataColumn) {
            switch (r.record.direction) {
            case TrafficRecord::Direction::Tx: return QBrush(QColor(0x15, 0x65, 0xc0));
            case TrafficRecord::Direction::Rx: return QBrush(QColor(0x2e, 0x7d, 0x32));
            case TrafficRecord::Direction::Discarded: return QBrush(QColor(0xc6, 0x28, 0x28));
            }
        }
        break;
    case Qt::FontRole:
        if (index.column() == DataColumn)
            return QFontDatabase::systemFont(QFontDatabase::FixedFont);
        break;
    case DirectionRole: return int(r.record.direction);
    case ConnectionRole: return r.connectionId;
    default: break;
    }
    return {};
}

QVariant FrameMonitorModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return QAbstractTableModel::headerData(section, orientation, role);
    switch (section) {
    case TimeColumn: return tr("Time");
    case LinkColumn: return tr("Link");
    case DirectionColumn: return tr("Dir.");
    case DataColumn: return tr("Frame (hex)");
    case MeaningColumn: return tr("Meaning");
    }
    return {};
}

void FrameMonitorModel::retranslate()
{
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
}

} // namespace dd
