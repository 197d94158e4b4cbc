#include "ui/shell/stopguard.h"

#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QKeyEvent>
#include <QToolButton>

namespace dd {

namespace {
constexpr int StripPadding = 4; // around the dialog's STOP button
const char *const StripHeightProperty = "dd_stopStripHeight";
} // namespace

StopGuard::StopGuard(QAction *stop, QObject *parent)
    : QObject(parent)
    , m_stop(stop)
{
    // A platform's own file dialog runs outside Qt's event delivery: F12 and Esc would not
    // reach the filter, and it could not carry a STOP button.
    QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs, true);
    qApp->installEventFilter(this);
}

StopGuard::~StopGuard()
{
    qApp->removeEventFilter(this);
}

bool StopGuard::isStopKey(const QKeyEvent *event)
{
    return event->key() == Qt::Key_F12 || event->key() == Qt::Key_Escape;
}

bool StopGuard::eventFilter(QObject *watched, QEvent *event)
{
    switch (event->type()) {
    case QEvent::ShortcutOverride: {
        auto *key = static_cast<QKeyEvent *>(event);
        if (m_resending || !isStopKey(key))
            break;
        // Ours: no shortcut takes it; the key press follows and is handled below.
        key->accept();
        return true;
    }
    case QEvent::KeyPress: {
        auto *key = static_cast<QKeyEvent *>(event);
        // Key events reach the window (QWindow) first, then its focus widget: act once, on the
        // widget.
        if (m_resending || !isStopKey(key) || !watched->isWidgetType() || !m_stop)
            break;
        if (!key->isAutoRepeat())
            m_stop->trigger();
        if (key->key() == Qt::Key_Escape) {
            // Then what Esc does where it was pressed (close a dialog or menu, cancel an edit).
            QPointer<QObject> target(watched);
            QKeyEvent copy(key->type(), key->key(), key->modifiers(), key->text(), key->isAutoRepeat(),
                           ushort(key->count()));
            m_resending = true;
            if (target)
                QCoreApplication::sendEvent(target, &copy);
            m_resending = false;
        }
        return true;
    }
    case QEvent::Polish:
        if (auto *dialog = qobject_cast<QDialog *>(watched); dialog && dialog->isWindow())
            equip(dialog);
        break;
    case QEvent::Resize:
    case QEvent::LayoutDirectionChange:
        if (auto *dialog = qobject_cast<QDialog *>(watched); dialog && dialog->property(StripHeightProperty).isValid())
            place(dialog);
        break;
    default: break;
    }
    return QObject::eventFilter(watched, event);
}

void StopGuard::equip(QDialog *dialog)
{
    if (dialog->findChild<QToolButton *>(QLatin1String(DialogStopButtonName), Qt::FindDirectChildrenOnly))
        return;
    auto *button = new QToolButton(dialog);
    button->setObjectName(QLatin1String(DialogStopButtonName));
    button->setDefaultAction(m_stop);
    button->setToolButtonStyle(Qt::ToolButtonTextOnly);
    button->setFocusPolicy(Qt::NoFocus); // Enter and Space keep their meaning in the dialog
    button->setStyleSheet(QStringLiteral("QToolButton { background: #d32f2f; color: white; font-weight: bold;"
                                         " border: 1px solid #8e0000; border-radius: 3px; padding: 2px 12px; }"
                                         "QToolButton:hover { background: #e53935; }"
                                         "QToolButton:pressed { background: #b71c1c; }"));
    // A strip above the dialog's own contents: the dialog's layout lays out inside the
    // contents margins, so nothing of the dialog is covered.
    const int strip = button->sizeHint().height() + 2 * StripPadding;
    QMargins m = dialog->contentsMargins();
    m.setTop(m.top() + strip);
    dialog->setContentsMargins(m);
    dialog->setProperty(StripHeightProperty, strip);
    place(dialog);
    button->show();
    button->raise();
}

void StopGuard::place(QDialog *dialog)
{
    auto *button = dialog->findChild<QToolButton *>(QLatin1String(DialogStopButtonName), Qt::FindDirectChildrenOnly);
    if (!button)
        return;
    const QSize size = button->sizeHint();
    const int x = dialog->isRightToLeft() ? StripPadding : dialog->width() - size.width() - StripPadding;
    button->setGeometry(x, StripPadding, size.width(), size.height());
    button->raise();
}

} // namespace dd
