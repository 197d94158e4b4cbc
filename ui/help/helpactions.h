#pragma once

#include <QObject>
#include <QPointer>

class QAction;
class QMenu;

namespace dd {

class MainWindow;
class ShortcutsDialog;
class UserGuideDialog;

// The Help menu's User guide (F1, anywhere in the window) and Keyboard shortcuts entries;
// each opens its dialog (non-modal, one at a time: a second request raises it).
class HelpActions : public QObject
{
    Q_OBJECT
public:
    HelpActions(MainWindow *window, QMenu *helpMenu);

    QAction *guideAction() const { return m_guide; }
    QAction *shortcutsAction() const { return m_shortcuts; }
    UserGuideDialog *guideDialog() const;     // null until opened, and after it is closed
    ShortcutsDialog *shortcutsDialog() const; // the same

private:
    void retranslate();
    void showGuide();
    void showShortcuts();

    MainWindow *m_window;
    QAction *m_guide = nullptr;
    QAction *m_shortcuts = nullptr;
    QPointer<UserGuideDialog> m_guideDialog;
    QPointer<ShortcutsDialog> m_shortcutsDialog;
};

} // namespace dd
