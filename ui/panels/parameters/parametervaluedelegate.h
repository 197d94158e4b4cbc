#pragma once

#include <QStyledItemDelegate>

namespace dd {

class ParameterTableModel;

// The editor of the Parameters tab's Value column: a line edit with a
// ParameterValueValidator. While the text is not acceptable (malformed, out of range,
// read-only) the editor is outlined red, its tooltip and problemChanged() say why, and
// Enter does not commit: valueRefused() reports the reason instead and the editor stays
// open. Nothing reaches the model — let alone the drive — that the validator refuses.
class ParameterValueDelegate : public QStyledItemDelegate
{
    Q_OBJECT
public:
    explicit ParameterValueDelegate(ParameterTableModel *model, QObject *parent = nullptr);

    QWidget *createEditor(QWidget *parent, const QStyleOptionViewItem &option, const QModelIndex &index) const override;
    void setEditorData(QWidget *editor, const QModelIndex &index) const override;
    void setModelData(QWidget *editor, QAbstractItemModel *model, const QModelIndex &index) const override;

signals:
    // While typing: the reason the text would be refused (empty: acceptable).
    void problemChanged(const QString &reason) const;
    // A commit was refused (Enter, or the editor lost focus): nothing was changed.
    void valueRefused(const QString &reason) const;

protected:
    bool eventFilter(QObject *object, QEvent *event) override;

private:
    QString problemOf(QWidget *editor) const;
    void showProblem(QWidget *editor, const QString &reason) const;

    ParameterTableModel *m_model = nullptr;
};

} // namespace dd
