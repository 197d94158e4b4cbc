#pragma once

#include "core/link/trafficrecord.h"

#include <QSortFilterProxyModel>

namespace dd {

class FrameMonitorModel;

// What the frame monitor shows of its FrameMonitorModel: frames of some directions, of one
// link or all, and containing a text (case-insensitive, in the hex bytes — with or without
// the spaces —, the meaning, the note or the link name).
class FrameMonitorFilter : public QSortFilterProxyModel
{
    Q_OBJECT
public:
    enum DirectionFlag { Tx = 0x1, Rx = 0x2, Discarded = 0x4, AllDirections = 0x7 };
    Q_DECLARE_FLAGS(Directions, DirectionFlag)

    explicit FrameMonitorFilter(QObject *parent = nullptr);

    void setFrameModel(FrameMonitorModel *model);
    FrameMonitorModel *frameModel() const { return m_model; }

    void setText(const QString &text);
    QString text() const { return m_text; }
    void setDirections(Directions directions);
    Directions directions() const { return m_directions; }
    void setLink(const QString &link); // empty: every link
    QString link() const { return m_link; }

    // Whether a row of the frame model passes the filter.
    bool accepts(int sourceRow) const;

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    static DirectionFlag flagOf(TrafficRecord::Direction d);

    FrameMonitorModel *m_model = nullptr;
    QString m_text;
    QString m_compactText; // without spaces, for hex
    Directions m_directions = AllDirections;
    QString m_link;
};

} // namespace dd

Q_DECLARE_OPERATORS_FOR_FLAGS(dd::FrameMonitorFilter::Directions)
