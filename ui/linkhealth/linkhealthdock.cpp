#include "ui/linkhealth/linkhealthdock.h"

#include "core/drive/drivehub.h"

#include <QEvent>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace dd {

namespace {
enum Column {
    ColDrive,
    ColRequests,
    ColAnswered,
    ColTurnaround,
    ColTimeouts,
    ColChecksum,
    ColLate,
    ColRetries,
    ColBusyLine,
    ColTimeout,
    ColGap,
    ColumnCount
};

// The drive a frame concerns: its first data byte in every family (serial frames, servo-can
// and shuoke CAN data).
int addressOf(const TrafficRecord &r)
{
    return r.bytes.isEmpty() ? -1 : quint8(r.bytes.at(0));
}
} // namespace

LinkHealthDock::LinkHealthDock(DriveHub *hub, QWidget *parent)
    : QDockWidget(parent)
{
    setObjectName(QStringLiteral("linkHealthDock"));
    setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable | QDockWidget::DockWidgetClosable);
    auto *body = new QWidget(this);
    m_table = new QTableWidget(0, ColumnCount, body);
    m_table->setObjectName(QStringLiteral("linkHealthTable"));
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_hint = new QLabel(body);
    m_hint->setWordWrap(true);
    auto *layout = new QVBoxLayout(body);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_hint);
    setWidget(body);
    if (hub)
        connect(hub, &DriveHub::trafficRecorded, this, &LinkHealthDock::addTraffic);
    m_refresh.setInterval(1000);
    connect(&m_refresh, &QTimer::timeout, this, [this] {
        if (m_dirty && isVisible())
            refresh();
    });
    m_refresh.start();
    retranslate();
}

void LinkHealthDock::addTraffic(int id, const TrafficRecord &r)
{
    m_linkNames.insert(id, r.link);
    if (r.direction == TrafficRecord::Direction::Tx) {
        const int address = addressOf(r);
        if (address > 0 && !m_health.contains({id, address})) {
            LinkHealth h;
            h.setAddress(address);
            m_health.insert({id, address}, h);
        }
    }
    for (auto it = m_health.begin(); it != m_health.end(); ++it)
        if (it.key().first == id)
            it.value().add(r);
    m_dirty = true;
}

LinkHealth::Summary LinkHealthDock::summary(int id, int address) const
{
    return m_health.value({id, address}).summary();
}

void LinkHealthDock::clear()
{
    m_health.clear();
    m_dirty = true;
    refresh();
}

void LinkHealthDock::refresh()
{
    m_dirty = false;
    QList<QPair<int, int>> keys = m_health.keys();
    std::sort(keys.begin(), keys.end());
    m_table->setRowCount(int(keys.size()));
    auto ms = [](double v) { return QString::number(v, 'f', 1); };
    for (int row = 0; row < keys.size(); ++row) {
        const LinkHealth::Summary s = m_health.value(keys.at(row)).summary();
        const QStringList cells{
            tr("%1, address %2").arg(m_linkNames.value(keys.at(row).first)).arg(keys.at(row).second),
            QString::number(s.requests),
            QString::number(s.answered),
            s.answered ? tr("%1 / %2 / %3 ms").arg(ms(s.minMs), ms(s.medianMs), ms(s.maxMs)) : QStringLiteral("—"),
            QString::number(s.timeouts),
            QString::number(s.checksumErrors),
            QString::number(s.lateReplies),
            QString::number(s.retries),
            QString::number(s.busyLineSends),
            s.answered ? tr("%1 ms").arg(s.recommendedTimeoutMs) : QStringLiteral("—"),
            tr("%1 ms").arg(s.recommendedGapMs),
        };
        for (int c = 0; c < ColumnCount; ++c) {
            auto *item = new QTableWidgetItem(cells.at(c));
            if (c != ColDrive)
                item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(row, c, item);
        }
    }
}

void LinkHealthDock::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDockWidget::changeEvent(event);
}

void LinkHealthDock::retranslate()
{
    setWindowTitle(tr("Link health"));
    m_table->setHorizontalHeaderLabels({tr("Drive"), tr("Requests"), tr("Answered"),
                                        tr("Turnaround min / median / max"), tr("Timeouts"), tr("Checksum errors"),
                                        tr("Late or duplicated"), tr("Retries"), tr("Sent on a busy line"),
                                        tr("Recommended timeout"), tr("Recommended gap")});
    m_hint->setText(tr("From the traffic seen so far. The recommended timeout is the reply allowance beyond the wire "
                       "time (drivedesk-cli --timeout); the gap is the quiet time between requests that lets late "
                       "replies land first. Requests sent on a busy line went out although the line was never quiet "
                       "(another master on the bus, or a drive sending on its own): no timeout or gap helps there."));
    refresh();
}

} // namespace dd
