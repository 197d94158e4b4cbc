#include "ui/help/shortcutsdialog.h"

#include <QDialogButtonBox>
#include <QEvent>
#include <QHeaderView>
#include <QKeySequence>
#include <QTableWidget>
#include <QVBoxLayout>

namespace dd {

ShortcutsDialog::ShortcutsDialog(QWidget *parent)
    : QDialog(parent)
{
    setObjectName(QStringLiteral("shortcutsDialog"));
    m_table = new QTableWidget(this);
    m_table->setObjectName(QStringLiteral("shortcutsTable"));
    m_table->setColumnCount(2);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setWordWrap(true);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_table, 1);
    layout->addWidget(buttons);
    resize(640, 520);
    retranslate();
}

void ShortcutsDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void ShortcutsDialog::retranslate()
{
    setWindowTitle(tr("Keyboard shortcuts"));
    m_table->setHorizontalHeaderLabels({tr("Keys"), tr("What they do")});
    const auto keys = [](std::initializer_list<QKeySequence> list) {
        QStringList out;
        for (const QKeySequence &k : list)
            out << k.toString(QKeySequence::NativeText);
        return out.join(QLatin1String(" / "));
    };
    const QList<QPair<QString, QString>> rows = {
        {keys({QKeySequence(Qt::Key_Escape), QKeySequence(Qt::Key_F12)}),
         tr("STOP: stop every drive on every connection, from any window, dialog, menu or editor "
            "(Esc then also closes the dialog; F12 only stops)")},
        {keys({QKeySequence(Qt::Key_F1)}), tr("Open the user guide")},
        {keys({QKeySequence(Qt::CTRL | Qt::Key_K)}), tr("Connect… (open a port or CAN interface and scan it)")},
        {keys({QKeySequence::Quit}), tr("Quit")},
        {tr("Hold %1 on a jog button").arg(QKeySequence(Qt::Key_Space).toString(QKeySequence::NativeText)),
         tr("Motion: jog while held; letting go stops")},
        {keys({QKeySequence::Undo, QKeySequence::Redo}), tr("Parameters: undo / redo an edit")},
        {keys({QKeySequence::Copy}), tr("Parameters: copy the selected rows (also in the right-click menu)")},
        {keys({QKeySequence(Qt::Key_Plus), QKeySequence(Qt::Key_Minus)}), tr("Trend: zoom in / out")},
        {keys({QKeySequence(Qt::Key_Left), QKeySequence(Qt::Key_Right)}), tr("Trend: pan in time")},
        {keys({QKeySequence(Qt::Key_Home), QKeySequence(Qt::Key_0)}), tr("Trend: reset the zoom")},
        {keys({QKeySequence(Qt::Key_Delete), QKeySequence(Qt::Key_Backspace)}),
         tr("Trend and Tuning plots: remove the cursors")},
        {tr("Alt + underlined letter"), tr("Menus and buttons: the letter underlined in their name")},
    };
    m_table->setRowCount(int(rows.size()));
    for (int i = 0; i < rows.size(); ++i) {
        m_table->setItem(i, 0, new QTableWidgetItem(rows.at(i).first));
        m_table->setItem(i, 1, new QTableWidgetItem(rows.at(i).second));
    }
    m_table->resizeRowsToContents();
}

} // namespace dd
