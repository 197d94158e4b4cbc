#include "ui/bus/bustreedelegate.h"

namespace dd {

void BusTreeDelegate::initStyleOption(QStyleOptionViewItem *option, const QModelIndex &index) const
{
    QStyledItemDelegate::initStyleOption(option, index);
    option->textElideMode = index.parent().isValid() ? Qt::ElideRight : Qt::ElideMiddle;
}

} // namespace dd
