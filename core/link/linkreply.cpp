#include "core/link/linkreply.h"

#include <QMetaObject>

namespace dd {

LinkReply::LinkReply(QObject *parent)
    : QObject(parent)
{
}

void LinkReply::finishWithFrame(const QByteArray &frame)
{
    m_frame = frame;
    finishLater();
}

void LinkReply::finishWithCanFrame(const CanFrameData &frame)
{
    m_canFrame = frame;
    finishLater();
}

void LinkReply::finishWithRegisters(const QList<quint16> &registers)
{
    m_registers = registers;
    finishLater();
}

void LinkReply::finishWithError(const Error &error)
{
    m_error = error;
    finishLater();
}

void LinkReply::finishEmpty()
{
    finishLater();
}

void LinkReply::finishLater()
{
    if (m_finished)
        return;
    m_finished = true;
    QMetaObject::invokeMethod(this, &LinkReply::finished, Qt::QueuedConnection);
}

} // namespace dd
