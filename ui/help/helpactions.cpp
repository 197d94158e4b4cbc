#include "ui/help/helpactions.h"

#include "ui/help/shortcutsdialog.h"
#include "ui/help/userguidedialog.h"
#include "ui/shell/languagemanager.h"
#include "ui/shell/mainwindow.h"

#include <QAction>
#include <QMenu>

namespace dd {

HelpActions::HelpActions(MainWindow *window, QMenu *helpMenu)
    : QObject(window)
    , m_window(window)
{
    m_guide = new QAction(window);
    m_guide->setObjectName(QStringLiteral("userGuideAction"));
    m_guide->setShortcut(QKeySequence(Qt::Key_F1));
    m_guide->setShortcutContext(Qt::ApplicationShortcut);
    window->addAction(m_guide); // F1 works whatever has the focus
    connect(m_guide, &QAction::triggered, this, &HelpActions::showGuide);
    m_shortcuts = new QAction(window);
    m_shortcuts->setObjectName(QStringLiteral("shortcutsAction"));
    connect(m_shortcuts, &QAction::triggered, this, &HelpActions::showShortcuts);
    QAction *first = helpMenu->actions().value(0);
    helpMenu->insertAction(first, m_guide);
    helpMenu->insertAction(first, m_shortcuts);
    if (first)
        helpMenu->insertSeparator(first);
    connect(window->languageManager(), &LanguageManager::languageChanged, this, &HelpActions::retranslate);
    retranslate();
}

UserGuideDialog *HelpActions::guideDialog() const
{
    return m_guideDialog;
}

ShortcutsDialog *HelpActions::shortcutsDialog() const
{
    return m_shortcutsDialog;
}

void HelpActions::retranslate()
{
    m_guide->setText(tr("&User guide"));
    m_shortcuts->setText(tr("&Keyboard shortcuts"));
}

void HelpActions::showGuide()
{
    if (!m_guideDialog) {
        m_guideDialog = new UserGuideDialog(m_window);
        m_guideDialog->setAttribute(Qt::WA_DeleteOnClose);
    }
    m_guideDialog->show();
    m_guideDialog->raise();
    m_guideDialog->activateWindow();
}

void HelpActions::showShortcuts()
{
    if (!m_shortcutsDialog) {
        m_shortcutsDialog = new ShortcutsDialog(m_window);
        m_shortcutsDialog->setAttribute(Qt::WA_DeleteOnClose);
    }
    m_shortcutsDialog->show();
    m_shortcutsDialog->raise();
    m_shortcutsDialog->activateWindow();
}

} // namespace dd
