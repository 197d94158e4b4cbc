#pragma once

#include <QAction>

class QToolBar;

namespace dd {

// STOP: stops every drive on every connection (DriveHub::stopAll: emergency stop where the
// family has one). Its keys, Esc and F12 (stopShortcuts()), are not QAction shortcuts (a
// modal dialog blocks those): StopGuard takes them in every window, dialog, menu and editor.
// F12 rather than Ctrl+Space: Ctrl+Space toggles the input method on most Chinese desktops.
// Always enabled, even with nothing connected.
class StopAction : public QAction
{
    Q_OBJECT
public:
    explicit StopAction(QObject *parent = nullptr);

    static QList<QKeySequence> stopShortcuts();
    // Adds the action as a big red button at the front of `toolBar`.
    void addTo(QToolBar *toolBar);
    void retranslate();
};

} // namespace dd
