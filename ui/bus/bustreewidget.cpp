#include "ui/bus/bustreewidget.h"

#include "ui/bus/bustreedelegate.h"
#include "ui/bus/drivedirectory.h"
#include "ui/common/displaytext.h"

#include <QEvent>
#include <QHeaderView>
#include <QMenu>
#include <QStyle>

namespace dd {

namespace {
QString linkText(const ConnectionSettings &s)
{
    QString text = s.linkName();
    if (!s.isCan() && s.baud > 0)
        text += QStringLiteral(" @ %1").arg(s.baud);
    if (s.isCan() && s.bitrate > 0)
        text += QStringLiteral(" @ %1 kbit/s").arg(s.bitrate / 1000);
    return text;
}
} // namespace

BusTreeWidget::BusTreeWidget(DriveDirectory *directory, QWidget *parent)
    : QTreeWidget(parent)
    , m_directory(directory)
{
    setColumnCount(ColumnCount);
    setUniformRowHeights(true);
    setAlternatingRowColors(true);
    setSelectionMode(QAbstractItemView::ExtendedSelection);
    setContextMenuPolicy(Qt::CustomContextMenu);
    // Every column in view without sideways scrolling: the name takes what is left and is
    // elided (links in the middle, drives at the end after their address: BusTreeDelegate);
    // its tool tip has the full text. State, position and firmware fit their contents.
    setTextElideMode(Qt::ElideMiddle);
    setItemDelegate(new BusTreeDelegate(this));
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    header()->setStretchLastSection(false);
    header()->setSectionResizeMode(NameColumn, QHeaderView::Stretch);
    header()->setSectionResizeMode(StateColumn, QHeaderView::ResizeToContents);
    header()->setSectionResizeMode(PositionColumn, QHeaderView::ResizeToContents);
    header()->setSectionResizeMode(FirmwareColumn, QHeaderView::ResizeToContents);
    retranslate();

    connect(directory, &DriveDirectory::connectionAdded, this, &BusTreeWidget::onConnectionAdded);
    connect(directory, &DriveDirectory::connectionRemoved, this, &BusTreeWidget::onConnectionRemoved);
    connect(directory, &DriveDirectory::linkStateChanged, this, [this](int id) {
        updateConnection(id);
        for (int a : m_directory->drives(id))
            updateDrive(id, a);
    });
    connect(directory, &DriveDirectory::driveAdded, this, &BusTreeWidget::onDriveAdded);
    connect(directory, &DriveDirectory::driveChanged, this, &BusTreeWidget::updateDrive);
    connect(this, &QTreeWidget::itemSelectionChanged, this, &BusTreeWidget::onSelectionChanged);
    connect(this, &QWidget::customContextMenuRequested, this, &BusTreeWidget::showContextMenu);

    for (int id : directory->connections()) {
        onConnectionAdded(id);
        for (int a : directory->drives(id))
            onDriveAdded(id, a);
    }
}

QTreeWidgetItem *BusTreeWidget::connectionItem(int id) const
{
    for (int i = 0; i < topLevelItemCount(); ++i)
        if (topLevelItem(i)->data(0, ConnectionRole).toInt() == id)
            return topLevelItem(i);
    return nullptr;
}

QTreeWidgetItem *BusTreeWidget::driveItem(int id, int address) const
{
    QTreeWidgetItem *c = connectionItem(id);
    if (!c)
        return nullptr;
    for (int i = 0; i < c->childCount(); ++i)
        if (c->child(i)->data(0, AddressRole).toInt() == address)
            return c->child(i);
    return nullptr;
}

void BusTreeWidget::selectDrive(int id, int address)
{
    QTreeWidgetItem *item = id ? driveItem(id, address) : nullptr;
    if (item)
        setCurrentItem(item);
    else
        clearSelection();
}

int BusTreeWidget::selectedConnection() const
{
    const QList<QTreeWidgetItem *> items = selectedItems();
    return items.isEmpty() ? 0 : items.first()->data(0, ConnectionRole).toInt();
}

void BusTreeWidget::onConnectionAdded(int id)
{
    if (connectionItem(id))
        return;
    auto *item = new QTreeWidgetItem(this);
    item->setData(0, ConnectionRole, id);
    item->setData(0, AddressRole, 0);
    item->setIcon(0, style()->standardIcon(QStyle::SP_DriveNetIcon));
    item->setFirstColumnSpanned(true); // the link name is long; drives use the columns
    item->setExpanded(true);
    updateConnection(id);
}

void BusTreeWidget::onConnectionRemoved(int id)
{
    delete connectionItem(id);
}

void BusTreeWidget::onDriveAdded(int id, int address)
{
    QTreeWidgetItem *parent = connectionItem(id);
    if (!parent || driveItem(id, address))
        return;
    auto *item = new QTreeWidgetItem;
    item->setData(0, ConnectionRole, id);
    item->setData(0, AddressRole, address);
    // Keep the drives in address order.
    int row = 0;
    while (row < parent->childCount() && parent->child(row)->data(0, AddressRole).toInt() < address)
        ++row;
    parent->insertChild(row, item);
    parent->setExpanded(true);
    updateDrive(id, address);
    updateConnection(id);
}

void BusTreeWidget::updateConnection(int id)
{
    QTreeWidgetItem *item = connectionItem(id);
    if (!item)
        return;
    const ConnectionSettings s = m_directory->connectionSettings(id);
    const bool lost = m_directory->linkState(id) == DriveDirectory::LinkState::Lost;
    const int n = m_directory->drives(id).size();
    const QString state = lost ? tr("link lost") : tr("%n drive(s)", nullptr, n);
    item->setText(NameColumn, tr("%1 — %2 (%3)").arg(familyId(s.family), linkText(s), state));
    item->setToolTip(NameColumn, lost ? m_directory->linkError(id) : linkText(s));
    item->setForeground(NameColumn, lost ? QBrush(QColor(0xc6, 0x28, 0x28)) : QBrush());
}

void BusTreeWidget::updateDrive(int id, int address)
{
    QTreeWidgetItem *item = driveItem(id, address);
    if (!item)
        return;
    const DriveInfo info = m_directory->info(id, address);
    const DriveStatus &s = info.status;
    // Address first: what tells two drives of a link apart stays in view when elided.
    item->setText(NameColumn, tr("#%1 %2").arg(address).arg(DisplayText::familyName(info.identity.family)));
    QString tip = tr("%1, address %2").arg(DisplayText::familyName(info.identity.family)).arg(address);
    if (!info.identity.model.isEmpty())
        tip += QStringLiteral("\n") + tr("Model: %1").arg(info.identity.model);
    item->setToolTip(NameColumn, tip);
    item->setText(FirmwareColumn, info.identity.firmware);
    item->setText(PositionColumn, DisplayText::position(s));
    item->setTextAlignment(PositionColumn, Qt::AlignRight | Qt::AlignVCenter);
    const QString state = DisplayText::summary(s);
    if (s.alarmCode) {
        item->setIcon(StateColumn, style()->standardIcon(QStyle::SP_MessageBoxWarning));
        item->setForeground(StateColumn, QBrush(QColor(0xc6, 0x28, 0x28)));
    } else {
        item->setIcon(StateColumn, QIcon());
        item->setForeground(StateColumn, QBrush());
    }
    item->setText(StateColumn, state);
    item->setToolTip(StateColumn, DisplayText::summary(s));
}

void BusTreeWidget::onSelectionChanged()
{
    const QList<QTreeWidgetItem *> items = selectedItems();
    const int id = items.isEmpty() ? 0 : items.first()->data(0, ConnectionRole).toInt();
    const int address = items.isEmpty() ? 0 : items.first()->data(0, AddressRole).toInt();
    emit driveSelected(address > 0 ? id : 0, address);
    emit connectionSelected(id);
}

QList<int> BusTreeWidget::selectedDrives(int id) const
{
    QList<int> out;
    for (const QTreeWidgetItem *item : selectedItems()) {
        const int a = item->data(0, AddressRole).toInt();
        if (a > 0 && item->data(0, ConnectionRole).toInt() == id)
            out << a;
    }
    std::sort(out.begin(), out.end());
    return out;
}

void BusTreeWidget::showContextMenu(const QPoint &pos)
{
    QTreeWidgetItem *item = itemAt(pos);
    if (!item)
        return;
    const int id = item->data(0, ConnectionRole).toInt();
    const int address = item->data(0, AddressRole).toInt();
    QMenu menu(this);
    if (address > 0)
        menu.addAction(tr("Refresh identity"), this, [this, id, address] { m_directory->refresh(id, address); });
    if (address > 0) {
        QList<int> selected = selectedDrives(id);
        if (!selected.contains(address))
            selected = {address};
        QList<int> others = selected;
        others.removeAll(address);
        menu.addSeparator();
        menu.addAction(tr("Apply backup to %n drive(s)…", nullptr, int(selected.size())), this,
                       [this, id, selected] { emit applyBackupRequested(id, selected); });
        menu.addAction(tr("Copy parameters from drive %1 to %n drive(s)…", nullptr, int(others.size())).arg(address),
                       this, [this, id, address, others] { emit copyParametersRequested(id, address, others); })
            ->setEnabled(!others.isEmpty());
        menu.addAction(tr("Compare %n drive(s)…", nullptr, int(selected.size())), this,
                       [this, id, selected] { emit compareRequested(id, selected); });
        menu.addSeparator();
    }
    menu.addAction(tr("Scan again"), this, [this, id] { emit rescanRequested(id); });
    menu.addAction(tr("Disconnect"), this, [this, id] { emit disconnectRequested(id); });
    menu.exec(viewport()->mapToGlobal(pos));
}

void BusTreeWidget::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QTreeWidget::changeEvent(event);
}

void BusTreeWidget::retranslate()
{
    setHeaderLabels({tr("Drive"), tr("State"), tr("Position"), tr("Firmware")});
    for (int id : m_directory ? m_directory->connections() : QList<int>()) {
        updateConnection(id);
        for (int a : m_directory->drives(id))
            updateDrive(id, a);
    }
}

} // namespace dd
