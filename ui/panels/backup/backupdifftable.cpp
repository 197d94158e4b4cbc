#include "ui/panels/backup/backupdifftable.h"

#include "core/params/parameterdictionary.h"

#include <QColor>
#include <QHeaderView>

namespace dd {

namespace {
constexpr int IndexRole = Qt::UserRole + 1;

bool restorable(const DiffEntry &e)
{
    return e.fileValue && e.access != Access::ReadOnly
        && (e.status == DiffStatus::Different || e.status == DiffStatus::OnlyInFile
            || e.status == DiffStatus::NotReadable);
}
} // namespace

BackupDiffTable::BackupDiffTable(QWidget *parent)
    : QTableWidget(0, ColumnCount, parent)
{
    setObjectName(QStringLiteral("backupDiffTable"));
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setAlternatingRowColors(true);
    verticalHeader()->hide();
    horizontalHeader()->setStretchLastSection(true);
    connect(this, &QTableWidget::itemChanged, this, [this](QTableWidgetItem *item) {
        if (!m_filling && item->column() == Parameter)
            emit checkedChanged();
    });
    retranslate();
}

void BackupDiffTable::setDiff(const ParameterDiff &diff, const ParameterDictionary &dictionary)
{
    m_diff = diff;
    m_dictionary = &dictionary;
    fill(false);
}

void BackupDiffTable::clearDiff()
{
    m_diff = ParameterDiff();
    m_dictionary = nullptr;
    setRowCount(0);
    emit checkedChanged();
}

void BackupDiffTable::setShowIdentical(bool show)
{
    m_showIdentical = show;
    applyVisibility();
}

QList<int> BackupDiffTable::checkableIndices() const
{
    QList<int> out;
    for (int row = 0; row < rowCount(); ++row)
        if (item(row, Parameter)->flags().testFlag(Qt::ItemIsUserCheckable))
            out << item(row, Parameter)->data(IndexRole).toInt();
    return out;
}

QList<int> BackupDiffTable::checkedIndices() const
{
    QList<int> out;
    for (int row = 0; row < rowCount(); ++row) {
        const QTableWidgetItem *it = item(row, Parameter);
        if (it->flags().testFlag(Qt::ItemIsUserCheckable) && it->checkState() == Qt::Checked)
            out << it->data(IndexRole).toInt();
    }
    return out;
}

void BackupDiffTable::setChecked(int parameterIndex, bool checked)
{
    const int row = rowOf(parameterIndex);
    if (row >= 0 && item(row, Parameter)->flags().testFlag(Qt::ItemIsUserCheckable))
        item(row, Parameter)->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
}

void BackupDiffTable::setAllChecked(bool checked)
{
    m_filling = true;
    for (int p : checkableIndices())
        setChecked(p, checked);
    m_filling = false;
    emit checkedChanged();
}

int BackupDiffTable::rowOf(int parameterIndex) const
{
    for (int row = 0; row < rowCount(); ++row)
        if (item(row, Parameter)->data(IndexRole).toInt() == parameterIndex)
            return row;
    return -1;
}

QString BackupDiffTable::statusText(DiffStatus status)
{
    switch (status) {
    case DiffStatus::Same: return tr("same");
    case DiffStatus::Different: return tr("different");
    case DiffStatus::OnlyInFile: return tr("only in the file (not read from the drive)");
    case DiffStatus::OnlyOnDrive: return tr("not in the file");
    case DiffStatus::NotReadable: return tr("write-only: the drive cannot report its value");
    }
    return {};
}

void BackupDiffTable::fill(bool keepChecks)
{
    m_filling = true;
    const QList<int> wasChecked = checkedIndices();
    setRowCount(int(m_diff.entries().size()));
    QVector<DiffEntry> defaults;
    m_diff.selectForWrite({}, &defaults);
    QList<int> defaultIndices;
    for (const DiffEntry &e : std::as_const(defaults))
        defaultIndices << e.index;
    for (int row = 0; row < m_diff.entries().size(); ++row) {
        const DiffEntry &e = m_diff.entries().at(row);
        auto *name = new QTableWidgetItem(m_dictionary ? m_dictionary->label(e.index) : e.key);
        name->setData(IndexRole, e.index);
        Qt::ItemFlags flags = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
        if (restorable(e)) {
            flags |= Qt::ItemIsUserCheckable;
            const bool checked = keepChecks ? wasChecked.contains(e.index) : defaultIndices.contains(e.index);
            name->setCheckState(checked ? Qt::Checked : Qt::Unchecked);
        }
        name->setFlags(flags);
        QString tip;
        if (e.access == Access::ReadOnly && e.status == DiffStatus::Different)
            tip = tr("Read-only: a restore cannot change it.");
        else if (e.communication && restorable(e))
            tip = tr("Changes how the drive communicates (address, baud rate): tick it to restore it too; "
                     "then connect again with the new settings.");
        name->setToolTip(tip);
        setItem(row, Parameter, name);
        setItem(row, FileValue,
                new QTableWidgetItem(e.fileValue ? QString::number(*e.fileValue) : QStringLiteral("—")));
        QString drive = e.driveValue ? QString::number(*e.driveValue) : QStringLiteral("—");
        if (e.access == Access::WriteOnly)
            drive = tr("not readable");
        setItem(row, DriveValue, new QTableWidgetItem(drive));
        auto *status = new QTableWidgetItem(statusText(e.status));
        status->setData(IndexRole, diffStatusId(e.status));
        if (e.status == DiffStatus::Different)
            status->setForeground(QColor(0xb2, 0x6a, 0x00));
        setItem(row, Status, status);
    }
    m_filling = false;
    applyVisibility();
    resizeColumnsToContents();
    emit checkedChanged();
}

void BackupDiffTable::applyVisibility()
{
    for (int row = 0; row < rowCount() && row < m_diff.entries().size(); ++row)
        setRowHidden(row, !m_showIdentical && m_diff.entries().at(row).status == DiffStatus::Same);
}

void BackupDiffTable::retranslate()
{
    setHorizontalHeaderLabels({tr("Parameter"), tr("In the file"), tr("On the drive"), tr("Difference")});
    if (m_dictionary)
        fill(true);
}

} // namespace dd
