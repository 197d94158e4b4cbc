#pragma once

#include <QStyledItemDelegate>

namespace dd {

// Draws the bus tree's rows. A link's label is elided in the middle (two links differ at
// their ends: "/dev/ttyUSB0" vs "/dev/ttyUSB1"); a drive's label starts with its address
// ("#5 Servo (Modbus)") and is elided at its end, so a narrow dock still shows which drive
// each row is. Tool tips keep the full texts.
class BusTreeDelegate : public QStyledItemDelegate
{
    Q_OBJECT
public:
    using QStyledItemDelegate::QStyledItemDelegate;

protected:
    void initStyleOption(QStyleOptionViewItem *option, const QModelIndex &index) const override;
};

} // namespace dd
