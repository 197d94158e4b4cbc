#include "ui/workspace/drivepanel.h"

#include "core/drive/driveresult.h"

#include <QEvent>

namespace dd {

DrivePanel::DrivePanel(const DriveContext &context, QWidget *parent)
    : QWidget(parent)
    , m_context(context)
{
    m_info.connectionId = context.connectionId;
    m_info.address = context.address;
    m_info.identity.family = context.family;
    m_info.identity.address = context.address;
    m_info.capabilities = context.capabilities;
}

void DrivePanel::setActive(bool active)
{
    if (m_active == active)
        return;
    m_active = active;
    activeChanged(active);
}

void DrivePanel::setDriveInfo(const DriveInfo &info)
{
    m_info = info;
    m_context.capabilities = info.capabilities;
    driveInfoChanged(info);
}

void DrivePanel::setStatus(const DriveStatus &status)
{
    m_info.status = status;
    statusChanged(status);
}

void DrivePanel::setAlarm(int code)
{
    m_info.status.alarmCode = code;
    alarmChanged(code);
}

void DrivePanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        emit titleChanged();
    }
    QWidget::changeEvent(event);
}

bool DrivePanel::reportResult(const DriveResult &result)
{
    if (!result.ok())
        reportError(result.error);
    return result.ok();
}

void DrivePanel::reportError(const Error &error)
{
    if (error.isError())
        emit errorOccurred(error);
}

} // namespace dd
