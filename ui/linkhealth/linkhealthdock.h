#pragma once

#include "core/link/linkhealth.h"

#include <QDockWidget>
#include <QHash>
#include <QPair>
#include <QTimer>

class QLabel;
class QTableWidget;

namespace dd {

class DriveHub;

// View → Link health: per drive (connection and address), from the traffic already seen on
// the links (DriveHub::trafficRecorded, the frames the frame monitor shows): requests,
// answered, turnaround min / median / max, timeouts, checksum errors, late or duplicated
// replies, retries, and the reply allowance and inter-request gap it recommends
// (LinkHealth, as `drivedesk-cli ping` reports them). Refreshed once a second.
class LinkHealthDock : public QDockWidget
{
    Q_OBJECT
public:
    explicit LinkHealthDock(DriveHub *hub, QWidget *parent = nullptr);

    QTableWidget *table() const { return m_table; }
    // The summary for drive `address` on connection `id` (empty if nothing was seen).
    LinkHealth::Summary summary(int id, int address) const;
    // A frame seen on connection `id` (connected to DriveHub::trafficRecorded).
    void addTraffic(int id, const TrafficRecord &record);
    void refresh(); // the table now (the timer does it once a second while shown)
    void clear();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();

    QHash<QPair<int, int>, LinkHealth> m_health; // (connection, address)
    QHash<int, QString> m_linkNames;
    QTableWidget *m_table = nullptr;
    QLabel *m_hint = nullptr;
    QTimer m_refresh;
    bool m_dirty = false;
};

} // namespace dd
