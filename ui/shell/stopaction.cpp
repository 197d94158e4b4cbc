#include "ui/shell/stopaction.h"

#include <QToolBar>
#include <QToolButton>

namespace dd {

StopAction::StopAction(QObject *parent)
    : QAction(parent)
{
    setObjectName(QStringLiteral("stopAll"));
    setAutoRepeat(false);
    retranslate();
}

QList<QKeySequence> StopAction::stopShortcuts()
{
    return {QKeySequence(Qt::Key_Escape), QKeySequence(Qt::Key_F12)};
}

void StopAction::addTo(QToolBar *toolBar)
{
    QAction *before = toolBar->actions().isEmpty() ? nullptr : toolBar->actions().first();
    toolBar->insertAction(before, this);
    if (auto *button = qobject_cast<QToolButton *>(toolBar->widgetForAction(this))) {
        button->setObjectName(QStringLiteral("stopButton"));
        button->setToolButtonStyle(Qt::ToolButtonTextOnly);
        button->setMinimumWidth(96);
        button->setStyleSheet(
            QStringLiteral("QToolButton { background: #d32f2f; color: white; font-weight: bold; font-size: 14pt;"
                           " border: 2px solid #8e0000; border-radius: 4px; padding: 4px 14px; }"
                           "QToolButton:hover { background: #e53935; }"
                           "QToolButton:pressed { background: #b71c1c; }"));
    }
}

void StopAction::retranslate()
{
    setText(tr("STOP"));
    QStringList keys;
    for (const QKeySequence &k : stopShortcuts())
        keys << k.toString(QKeySequence::NativeText);
    setToolTip(tr("Stop all drives on all connections (%1)").arg(keys.join(tr(" or "))));
    setStatusTip(toolTip());
}

} // namespace dd
