#include "ui/panels/parameters/parametercontextmenu.h"

#include "core/params/parameterinfo.h"
#include "ui/panels/parameters/parametertablemodel.h"

#include <QApplication>
#include <QClipboard>
#include <QLocale>
#include <QPointer>

namespace dd {

ParameterContextMenu::ParameterContextMenu(ParameterTableModel *model, int parameterIndex, const QList<int> &selected,
                                           std::function<void(int)> writeRow, bool canWrite, QWidget *parent)
    : QMenu(parent)
{
    setObjectName(QStringLiteral("parameterContextMenu"));
    QList<int> rows = selected;
    if (!rows.contains(parameterIndex))
        rows = {parameterIndex};
    QPointer<ParameterTableModel> m(model);

    m_copy = addAction(rows.size() > 1 ? tr("&Copy %n rows", nullptr, int(rows.size())) : tr("&Copy"));
    m_copy->setShortcut(QKeySequence::Copy);
    connect(m_copy, &QAction::triggered, this,
            [m, rows] { QApplication::clipboard()->setText(m ? copyText(m, rows) : QString()); });

    const ParameterInfo *info = model->info(parameterIndex);
    const bool writable = info && info->isWritable();
    if (info && info->defaultValue && writable) {
        const qint64 value = *info->defaultValue;
        m_reset = addAction(tr("&Reset to default (%1)").arg(QLocale().toString(value)));
        connect(m_reset, &QAction::triggered, this, [m, parameterIndex, value] {
            const int row = m ? m->rowOf(parameterIndex) : -1;
            if (row >= 0) // through setData: validated, undoable, marked as an edit to write
                m->setData(m->index(row, ParameterTableModel::Value), QString::number(value), Qt::EditRole);
        });
    } else {
        m_reset = addAction(!writable ? tr("Reset to default (read-only parameter)")
                                      : tr("Reset to default (the dictionary gives none)"));
        m_reset->setEnabled(false);
    }

    const bool changed = model->isChanged(parameterIndex);
    m_write = addAction(changed ? tr("&Write this row") : tr("Write this row (not edited)"));
    m_write->setEnabled(changed && canWrite);
    connect(m_write, &QAction::triggered, this, [writeRow, parameterIndex] {
        if (writeRow)
            writeRow(parameterIndex);
    });
}

QString ParameterContextMenu::copyText(const ParameterTableModel *model, const QList<int> &parameters)
{
    QStringList lines;
    const QLocale locale;
    for (int p : parameters) {
        const ParameterInfo *info = model->info(p);
        if (!info)
            continue;
        const std::optional<qint64> v = model->value(p);
        lines << QStringList{info->key, info->displayName(locale), v ? QString::number(*v) : QString(), info->unit}.join(
            QLatin1Char('\t'));
    }
    return lines.join(QLatin1Char('\n'));
}

} // namespace dd
