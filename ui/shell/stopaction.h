#pragma once

#include <QAction>

class QToolBar;

namespace dd {

// STOP: stops every drive on every connection (DriveHub::stopAll: emergency stop where the
// family has one). Shortcuts Esc and F12, application-wide (any window of the application
// that is not blocked by a modal dialog). F12 rather than Ctrl+Space: Ctrl+Space toggles
// the input method on most Chinese desktops, and F12 still works where a widget keeps Esc
// for itself (an open editor, a combo-box popup). Always enabled, even with nothing
// connected.
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
