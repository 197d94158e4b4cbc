#pragma once

#include <QObject>
#include <QPointer>

class QAction;
class QDialog;
class QKeyEvent;

namespace dd {

// Makes STOP reach every drive from every window of the application, whatever is open:
// an application-wide event filter (installed on qApp for as long as it lives).
//   - F12 anywhere — the main window, any dialog, modal or not, a message box, a file
//     dialog, an open menu or combo-box list, a cell editor — triggers `stop` and does
//     nothing else.
//   - Esc anywhere triggers `stop` too, and then still does what it does there: it closes
//     the dialog, menu or list, or cancels the cell edit (STOP + close). A panicking user
//     reaches for Esc; a STOP of a standing axis costs nothing.
//   - Every dialog (QDialog: ours, message boxes, file dialogs) gets a red STOP button in a
//     strip above its contents (`DialogStopButtonName`), so that STOP can be clicked while a
//     modal dialog blocks the main window's tool bar.
// The key presses are taken before any shortcut or widget (ShortcutOverride accepted), so no
// widget can keep them for itself. Native (platform) dialogs would bypass the filter: the guard
// sets Qt::AA_DontUseNativeDialogs. Auto-repeated key presses do not repeat the STOP.
class StopGuard : public QObject
{
    Q_OBJECT
public:
    explicit StopGuard(QAction *stop, QObject *parent = nullptr);
    ~StopGuard() override;

    static constexpr const char *DialogStopButtonName = "dialogStopButton";
    static bool isStopKey(const QKeyEvent *event);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void equip(QDialog *dialog);
    void place(QDialog *dialog);

    QPointer<QAction> m_stop;
    bool m_resending = false; // passing an Esc on to where it was going
};

} // namespace dd
