#include "core/link/serialreadsniffer.h"

#include <QEvent>
#include <QIODevice>
#include <QSocketNotifier>

namespace dd {

SerialReadSniffer::SerialReadSniffer(QObject *parent)
    : QObject(parent)
{
}

SerialReadSniffer::~SerialReadSniffer()
{
    detach();
}

bool SerialReadSniffer::attach(QIODevice *device)
{
    detach();
    if (!device || !device->isOpen())
        return false;
    const auto notifiers = device->findChildren<QSocketNotifier *>(Qt::FindDirectChildrenOnly);
    for (QSocketNotifier *n : notifiers) {
        if (n->type() == QSocketNotifier::Read) {
            m_device = device;
            m_notifier = n;
            n->installEventFilter(this);
            return true;
        }
    }
    return false;
}

void SerialReadSniffer::detach()
{
    if (m_notifier)
        m_notifier->removeEventFilter(this);
    m_notifier = nullptr;
    m_device = nullptr;
}

bool SerialReadSniffer::eventFilter(QObject *watched, QEvent *event)
{
    if (watched != m_notifier || event->type() != QEvent::SockAct || !m_device)
        return false;
    QPointer<QIODevice> device = m_device;
    // A transaction left open by someone else is not ours to end.
    if (device->isTransactionStarted())
        return false;
    device->startTransaction();
    // Deliver the event now, inside the transaction: the port reads the OS buffer, emits
    // readyRead, and the reader (e.g. the Modbus client) consumes what it wants.
    const bool handled = static_cast<QObject *>(watched)->event(event);
    // The reader may have closed the port meanwhile (close() ends the transaction).
    if (!device || !device->isTransactionStarted())
        return true;
    const qint64 unread = device->bytesAvailable();
    device->rollbackTransaction();
    const qint64 consumed = device->bytesAvailable() - unread;
    if (consumed > 0) {
        const QByteArray bytes = device->read(consumed);
        m_bytesSeen += quint64(bytes.size());
        emit bytesRead(bytes);
    }
    Q_UNUSED(handled);
    return true;
}

} // namespace dd
