#include "ui/panels/parameters/parametertablemodel.h"

#include "core/params/parameterdictionary.h"
#include "ui/common/displaytext.h"
#include "ui/panels/parameters/parametereditcommand.h"
#include "ui/panels/parameters/parametervaluevalidator.h"

#include <QBrush>
#include <QColor>
#include <QFont>
#include <QLocale>
#include <QUndoStack>

namespace dd {

namespace {
const QColor VerifiedColor(0x2e, 0x7d, 0x32);
const QColor FailedColor(0xc6, 0x28, 0x28);
const QColor ChangedBackground(0xff, 0xf3, 0xcd);
const QChar ChangedMark(0x25CF); // ●
const QChar UndoneMark(0x21B6);  // ↶ an undone write, to be written back
const QChar UnsavedMark(0x25C7); // ◇ written, not saved to EEPROM

bool appliesTo(const ParameterInfo &p, const QString &model)
{
    return p.models.isEmpty() || (!model.isEmpty() && p.models.contains(model, Qt::CaseInsensitive));
}
} // namespace

ParameterTableModel::ParameterTableModel(QObject *parent)
    : QAbstractTableModel(parent)
{
}

ParameterTableModel::~ParameterTableModel() = default;

void ParameterTableModel::setDictionary(std::shared_ptr<const ParameterDictionary> dictionary, const QString &model)
{
    beginResetModel();
    QHash<int, Row> old;
    for (const Row &r : std::as_const(m_rows))
        old.insert(r.info.index, r);
    m_dictionary = std::move(dictionary);
    m_rows.clear();
    m_rowOf.clear();
    if (m_dictionary) {
        for (const ParameterInfo &p : m_dictionary->parameters()) {
            if (!appliesTo(p, model))
                continue;
            Row r = old.value(p.index);
            r.info = p;
            m_rowOf.insert(p.index, int(m_rows.size()));
            m_rows.append(r);
        }
    }
    endResetModel();
    emit editsChanged();
}

int ParameterTableModel::rowOf(int parameterIndex) const
{
    return m_rowOf.value(parameterIndex, -1);
}

int ParameterTableModel::parameterAt(int row) const
{
    return row >= 0 && row < m_rows.size() ? m_rows.at(row).info.index : -1;
}

const ParameterInfo *ParameterTableModel::info(int parameterIndex) const
{
    const Row *r = rowFor(parameterIndex);
    return r ? &r->info : nullptr;
}

QList<int> ParameterTableModel::parameterIndices() const
{
    QList<int> out;
    for (const Row &r : m_rows)
        out << r.info.index;
    return out;
}

QList<int> ParameterTableModel::readableIndices() const
{
    QList<int> out;
    for (const Row &r : m_rows)
        if (r.info.isReadable())
            out << r.info.index;
    return out;
}

ParameterValue ParameterTableModel::driveValue(int parameterIndex) const
{
    const Row *r = rowFor(parameterIndex);
    return r ? r->drive : ParameterValue{};
}

std::optional<qint64> ParameterTableModel::editedValue(int parameterIndex) const
{
    const Row *r = rowFor(parameterIndex);
    return r ? r->edited : std::nullopt;
}

std::optional<qint64> ParameterTableModel::value(int parameterIndex) const
{
    const Row *r = rowFor(parameterIndex);
    if (!r)
        return std::nullopt;
    if (r->edited)
        return r->edited;
    return r->drive.isKnown() ? std::optional<qint64>(r->drive.value) : std::nullopt;
}

bool ParameterTableModel::rowChanged(const Row &r) const
{
    // A write-only parameter's edit always counts: the drive's value is not known, even
    // when it equals what was last written.
    return r.edited && (r.drive.source != ValueSource::ReadFromDrive || r.drive.value != *r.edited);
}

bool ParameterTableModel::isChanged(int parameterIndex) const
{
    const Row *r = rowFor(parameterIndex);
    return r && rowChanged(*r);
}

QList<int> ParameterTableModel::changedIndices() const
{
    QList<int> out;
    for (const Row &r : m_rows)
        if (rowChanged(r))
            out << r.info.index;
    return out;
}

ParameterTableModel::WriteState ParameterTableModel::writeState(int parameterIndex) const
{
    const Row *r = rowFor(parameterIndex);
    return r ? r->state : WriteState::None;
}

QString ParameterTableModel::writeMessage(int parameterIndex) const
{
    const Row *r = rowFor(parameterIndex);
    return r ? r->message : QString();
}

void ParameterTableModel::setDriveValues(const QMap<int, qint64> &values, ValueSource source)
{
    bool editsDropped = false;
    for (auto it = values.begin(); it != values.end(); ++it) {
        Row *r = rowFor(it.key());
        if (!r || (source == ValueSource::LastWritten && r->info.isReadable()))
            continue;
        r->drive = {it.value(), source};
        if (source == ValueSource::ReadFromDrive && r->edited && *r->edited == it.value()) {
            r->edited.reset();
            editsDropped = true;
        }
    }
    if (!m_rows.isEmpty())
        emit dataChanged(index(0, 0), index(int(m_rows.size()) - 1, ColumnCount - 1));
    if (editsDropped)
        emit editsChanged();
}

void ParameterTableModel::applyWriteResults(const QList<ParameterWriteResult> &results, const QList<int> &requested)
{
    QList<int> answered;
    for (const ParameterWriteResult &w : results) {
        Row *r = rowFor(w.index);
        if (!r)
            continue;
        answered << w.index;
        r->message = w.error;
        if (w.written && w.verified) {
            r->drive = {w.readBack, ValueSource::ReadFromDrive};
            r->edited.reset();
            r->state = WriteState::Verified;
        } else if (w.written && !w.readable) {
            r->drive = {w.requested, ValueSource::LastWritten};
            r->edited.reset();
            r->state = WriteState::WrittenOnly;
        } else if (w.written) {
            r->drive = {w.readBack, ValueSource::ReadFromDrive};
            r->state = WriteState::Failed;
            if (r->message.isEmpty())
                r->message = tr("the drive reads back %1").arg(w.readBack);
        } else {
            r->state = WriteState::Failed;
            if (r->message.isEmpty())
                r->message = tr("the drive did not accept the value");
        }
        emitRowChanged(rowOf(w.index));
    }
    for (int p : requested) {
        Row *r = rowFor(p);
        if (!r || answered.contains(p))
            continue;
        r->state = WriteState::NotAttempted;
        r->message = tr("not written: the write stopped before this parameter");
        emitRowChanged(rowOf(p));
    }
    emit editsChanged();
}

bool ParameterTableModel::isUndoneWrite(int parameterIndex) const
{
    const Row *r = rowFor(parameterIndex);
    return r && r->undoneWrite && rowChanged(*r);
}

void ParameterTableModel::setUnsaved(const QSet<int> &indices)
{
    if (indices == m_unsaved)
        return;
    m_unsaved = indices;
    if (!m_rows.isEmpty())
        emit dataChanged(index(0, Mark), index(int(m_rows.size()) - 1, Mark));
}

void ParameterTableModel::setEditedValue(int parameterIndex, std::optional<qint64> value, bool undoneWrite)
{
    Row *r = rowFor(parameterIndex);
    if (!r)
        return;
    r->edited = value;
    r->undoneWrite = undoneWrite && value.has_value();
    r->state = WriteState::None;
    r->message.clear();
    emitRowChanged(rowOf(parameterIndex));
    emit editsChanged();
}

Error ParameterTableModel::checkText(int parameterIndex, const QString &text, qint64 *value) const
{
    if (!m_dictionary)
        return {ErrorCode::InvalidArgument, tr("No parameter dictionary is loaded for this drive.")};
    return ParameterValueValidator::check(*m_dictionary, parameterIndex, text, value);
}

void ParameterTableModel::retranslate()
{
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    if (!m_rows.isEmpty())
        emit dataChanged(index(0, 0), index(int(m_rows.size()) - 1, ColumnCount - 1));
}

int ParameterTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_rows.size());
}

int ParameterTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant ParameterTableModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const Row &r = m_rows.at(index.row());
    const int column = index.column();
    const bool changed = rowChanged(r);
    switch (role) {
    case Qt::DisplayRole: return display(r, column);
    case Qt::EditRole:
        if (column == Value) {
            const std::optional<qint64> v = value(r.info.index);
            return v ? QString::number(*v) : QString();
        }
        return display(r, column);
    case SearchRole: return searchText(r);
    case ParameterIndexRole: return r.info.index;
    case Qt::TextAlignmentRole:
        if (column == Index || column == Value || column == DriveValue || column == Default)
            return int(Qt::AlignRight | Qt::AlignVCenter);
        if (column == Mark)
            return int(Qt::AlignCenter);
        return {};
    case Qt::FontRole:
        if (changed && (column == Value || column == Mark)) {
            QFont f;
            f.setBold(true);
            return f;
        }
        return {};
    case Qt::BackgroundRole:
        if (changed && column == Value)
            return QBrush(ChangedBackground);
        return {};
    case Qt::ForegroundRole:
        if (column == State && r.state == WriteState::Verified)
            return QBrush(VerifiedColor);
        if ((column == State && (r.state == WriteState::Failed || r.state == WriteState::NotAttempted))
            || (column == Mark && changed))
            return QBrush(column == Mark ? QColor(0xb2, 0x6a, 0x00) : FailedColor);
        return {};
    case Qt::ToolTipRole: return toolTip(r, column, changed);
    default: return {};
    }
}

QVariant ParameterTableModel::toolTip(const Row &r, int column, bool changed) const
{
    switch (column) {
    case Name: return r.info.description.text(QLocale());
    case Mark:
        if (!changed && m_unsaved.contains(r.info.index))
            return tr("Written to the drive's working memory but not saved to its EEPROM (EE-Set): "
                      "the drive forgets it when switched off.");
        [[fallthrough]];
    case Value:
        if (!r.info.isWritable())
            return tr("Read-only: the drive does not accept a new value.");
        if (changed && r.undoneWrite)
            return tr("Undone: the value the drive had before the last write. Write it to restore it "
                      "on the drive (the drive has %1 now).")
                .arg(r.drive.value);
        if (changed)
            return r.drive.source == ValueSource::ReadFromDrive
                ? tr("Edited: the drive has %1. Write it to send the new value.").arg(r.drive.value)
                : tr("Edited: not yet written to the drive.");
        return tr("Double-click to edit (%1 to %2).").arg(r.info.min).arg(r.info.max);
    case DriveValue:
        if (!r.info.isReadable())
            return tr("The drive cannot report this parameter: DriveDesk shows the value it last wrote.");
        return {};
    case State: return r.message.isEmpty() ? QVariant() : QVariant(r.message);
    default: return {};
    }
}

QVariant ParameterTableModel::display(const Row &r, int column) const
{
    const ParameterInfo &p = r.info;
    switch (column) {
    case Mark:
        if (rowChanged(r))
            return QString(r.undoneWrite ? UndoneMark : ChangedMark);
        return m_unsaved.contains(p.index) ? QString(UnsavedMark) : QString();
    case Index: return p.index;
    case Key: return p.key;
    case Name: return p.displayName(QLocale());
    case Value: {
        const std::optional<qint64> v = value(p.index);
        return v ? QVariant(QString::number(*v)) : QVariant(QString());
    }
    case DriveValue: return driveText(r);
    case Unit: return DisplayText::unit(p.unit);
    case Range: return QStringLiteral("%1 … %2").arg(p.min).arg(p.max);
    case Default: return p.defaultValue ? QString::number(*p.defaultValue) : QStringLiteral("—");
    case Access:
        switch (p.access) {
        case dd::Access::ReadWrite: return tr("read/write");
        case dd::Access::ReadOnly: return tr("read-only");
        case dd::Access::WriteOnly: return tr("write-only");
        }
        return {};
    case State: return stateText(r);
    default: return {};
    }
}

QString ParameterTableModel::driveText(const Row &r) const
{
    if (!r.info.isReadable()) {
        if (r.drive.source == ValueSource::LastWritten)
            return tr("not readable (last written: %1)").arg(r.drive.value);
        return tr("not readable");
    }
    return r.drive.isKnown() ? QString::number(r.drive.value) : QStringLiteral("—");
}

QString ParameterTableModel::stateText(const Row &r) const
{
    if (r.undoneWrite && rowChanged(r))
        return tr("undone: not yet written back");
    switch (r.state) {
    case WriteState::None: return QString();
    case WriteState::Verified: return tr("written, verified");
    case WriteState::WrittenOnly: return tr("written (cannot be read back)");
    case WriteState::Failed: return tr("failed: %1").arg(r.message);
    case WriteState::NotAttempted: return tr("not written");
    }
    return QString();
}

QString ParameterTableModel::searchText(const Row &r) const
{
    QStringList parts{QString::number(r.info.index), r.info.key};
    parts << r.info.name.allTexts();
    return parts.join(QLatin1Char(' '));
}

QVariant ParameterTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal)
        return {};
    if (role == Qt::ToolTipRole && section == Mark)
        return tr("%1 marks a value edited here that differs from the drive's; %2 an undone write, "
                  "not yet written back; %3 a value written but not saved to EEPROM")
            .arg(ChangedMark)
            .arg(UndoneMark)
            .arg(UnsavedMark);
    if (role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Mark: return QString(ChangedMark);
    case Index: return tr("Index");
    case Key: return tr("Key");
    case Name: return tr("Name");
    case Value: return tr("Value");
    case DriveValue: return tr("On the drive");
    case Unit: return tr("Unit");
    case Range: return tr("Range");
    case Default: return tr("Default");
    case Access: return tr("Access");
    case State: return tr("Last write");
    default: return {};
    }
}

Qt::ItemFlags ParameterTableModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsSelectable | Qt::ItemIsEnabled;
    if (index.column() == Value && index.row() < m_rows.size() && m_rows.at(index.row()).info.isWritable())
        f |= Qt::ItemIsEditable;
    return f;
}

bool ParameterTableModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (!index.isValid() || index.column() != Value || role != Qt::EditRole || index.row() >= m_rows.size())
        return false;
    const Row &r = m_rows.at(index.row());
    const int p = r.info.index;
    qint64 v = 0;
    if (Error e = checkText(p, value.toString(), &v)) {
        emit editRefused(p, e);
        return false;
    }
    std::optional<qint64> after = v;
    if (r.drive.source == ValueSource::ReadFromDrive && r.drive.value == v)
        after.reset(); // back to the drive's value: no longer an edit
    if (after == r.edited)
        return true;
    if (m_undo)
        m_undo->push(new ParameterEditCommand(this, p, r.edited, after));
    else
        setEditedValue(p, after);
    return true;
}

ParameterTableModel::Row *ParameterTableModel::rowFor(int parameterIndex)
{
    const int row = rowOf(parameterIndex);
    return row >= 0 ? &m_rows[row] : nullptr;
}

const ParameterTableModel::Row *ParameterTableModel::rowFor(int parameterIndex) const
{
    const int row = rowOf(parameterIndex);
    return row >= 0 ? &m_rows.at(row) : nullptr;
}

void ParameterTableModel::emitRowChanged(int row)
{
    if (row >= 0)
        emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
}

} // namespace dd
