#include "ui/framemonitor/framemonitorfilter.h"

#include "ui/framemonitor/framemonitormodel.h"

namespace dd {

FrameMonitorFilter::FrameMonitorFilter(QObject *parent)
    : QSortFilterProxyModel(parent)
{
}

void FrameMonitorFilter::setFrameModel(FrameMonitorModel *model)
{
    m_model = model;
    setSourceModel(model);
}

void FrameMonitorFilter::setText(const QString &text)
{
    const QString t = text.trimmed();
    if (t == m_text)
        return;
    m_text = t;
    m_compactText = t;
    m_compactText.remove(QLatin1Char(' '));
    invalidateRowsFilter();
}

void FrameMonitorFilter::setDirections(Directions directions)
{
    if (directions == m_directions)
        return;
    m_directions = directions;
    invalidateRowsFilter();
}

void FrameMonitorFilter::setLink(const QString &link)
{
    if (link == m_link)
        return;
    m_link = link;
    invalidateRowsFilter();
}

FrameMonitorFilter::DirectionFlag FrameMonitorFilter::flagOf(TrafficRecord::Direction d)
{
    switch (d) {
    case TrafficRecord::Direction::Tx: return Tx;
    case TrafficRecord::Direction::Rx: return Rx;
    case TrafficRecord::Direction::Discarded: return Discarded;
    }
    return Tx;
}

bool FrameMonitorFilter::accepts(int sourceRow) const
{
    if (!m_model || sourceRow < 0 || sourceRow >= m_model->rowCount())
        return false;
    const FrameMonitorModel::Row &row = m_model->row(sourceRow);
    const TrafficRecord &r = row.record;
    if (!m_directions.testFlag(flagOf(r.direction)))
        return false;
    if (!m_link.isEmpty() && r.link != m_link)
        return false;
    if (m_text.isEmpty())
        return true;
    const auto has = [this](const QString &s) { return s.contains(m_text, Qt::CaseInsensitive); };
    if (has(row.meaning) || has(r.note) || has(r.link))
        return true;
    const QString hex = r.hexText();
    if (has(hex))
        return true;
    if (!m_compactText.isEmpty()) {
        QString compact = hex;
        compact.remove(QLatin1Char(' '));
        return compact.contains(m_compactText, Qt::CaseInsensitive);
    }
    return false;
}

bool FrameMonitorFilter::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{
    return !sourceParent.isValid() && accepts(sourceRow);
}

} // namespace dd
