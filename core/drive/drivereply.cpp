#include "core/drive/drivereply.h"

#include <QMetaObject>

namespace dd {

DriveReply::DriveReply(QObject *parent)
    : QObject(parent)
{
}

void DriveReply::finish(const Error &error)
{
    if (m_finished)
        return;
    m_finished = true;
    m_error = error;
    QMetaObject::invokeMethod(this, &DriveReply::finished, Qt::QueuedConnection);
}

} // namespace dd
