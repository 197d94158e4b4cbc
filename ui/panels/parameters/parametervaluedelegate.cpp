#include "ui/panels/parameters/parametervaluedelegate.h"

#include "ui/panels/parameters/parametertablemodel.h"
#include "ui/panels/parameters/parametervaluevalidator.h"

#include <QKeyEvent>
#include <QLineEdit>
#include <QToolTip>

namespace dd {

ParameterValueDelegate::ParameterValueDelegate(ParameterTableModel *model, QObject *parent)
    : QStyledItemDelegate(parent)
    , m_model(model)
{
}

QWidget *ParameterValueDelegate::createEditor(QWidget *parent, const QStyleOptionViewItem &option,
                                              const QModelIndex &index) const
{
    if (index.column() != ParameterTableModel::Value)
        return QStyledItemDelegate::createEditor(parent, option, index);
    auto *edit = new QLineEdit(parent);
    edit->setObjectName(QStringLiteral("parameterValueEditor"));
    edit->setFrame(false);
    const int parameter = index.data(ParameterTableModel::ParameterIndexRole).toInt();
    edit->setValidator(new ParameterValueValidator(m_model->dictionary(), parameter, edit));
    connect(edit, &QLineEdit::textEdited, this, [this, edit] {
        const QString reason = problemOf(edit);
        showProblem(edit, reason);
        emit problemChanged(reason);
    });
    return edit;
}

void ParameterValueDelegate::setEditorData(QWidget *editor, const QModelIndex &index) const
{
    if (auto *edit = qobject_cast<QLineEdit *>(editor); edit && index.column() == ParameterTableModel::Value) {
        edit->setText(index.data(Qt::EditRole).toString());
        edit->selectAll();
        return;
    }
    QStyledItemDelegate::setEditorData(editor, index);
}

void ParameterValueDelegate::setModelData(QWidget *editor, QAbstractItemModel *model, const QModelIndex &index) const
{
    auto *edit = qobject_cast<QLineEdit *>(editor);
    if (!edit || index.column() != ParameterTableModel::Value) {
        QStyledItemDelegate::setModelData(editor, model, index);
        return;
    }
    const QString reason = problemOf(edit);
    if (!reason.isEmpty()) {
        emit valueRefused(reason);
        return;
    }
    model->setData(index, edit->text(), Qt::EditRole);
}

bool ParameterValueDelegate::eventFilter(QObject *object, QEvent *event)
{
    auto *edit = qobject_cast<QLineEdit *>(object);
    if (edit && event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent *>(event)->key();
        if (key == Qt::Key_Return || key == Qt::Key_Enter) {
            const QString reason = problemOf(edit);
            if (!reason.isEmpty()) {
                showProblem(edit, reason);
                emit valueRefused(reason);
                return true; // the editor stays open with the text
            }
        }
    }
    return QStyledItemDelegate::eventFilter(object, event);
}

QString ParameterValueDelegate::problemOf(QWidget *editor) const
{
    auto *edit = qobject_cast<QLineEdit *>(editor);
    const auto *validator = edit ? qobject_cast<const ParameterValueValidator *>(edit->validator()) : nullptr;
    return validator ? validator->reason(edit->text()) : QString();
}

void ParameterValueDelegate::showProblem(QWidget *editor, const QString &reason) const
{
    editor->setToolTip(reason);
    editor->setStyleSheet(reason.isEmpty() ? QString() : QStringLiteral("QLineEdit { border: 2px solid #c62828; }"));
    if (reason.isEmpty())
        QToolTip::hideText();
    else if (editor->isVisible())
        QToolTip::showText(editor->mapToGlobal(QPoint(0, editor->height())), reason, editor);
}

} // namespace dd
