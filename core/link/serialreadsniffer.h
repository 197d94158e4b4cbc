#pragma once

#include <QByteArray>
#include <QObject>
#include <QPointer>
#include <QSocketNotifier>

class QIODevice;

namespace dd {

// Shows the raw bytes that another object reads from a serial port it owns.
//
// QModbusRtuSerialClient reads its QSerialPort itself and reports only decoded PDUs: the
// bytes of a frame it throws away (an exception reply whose address byte differs from the
// request's, as the servo-modbus seed prescribes; noise; a late reply) never reach us.
// On Unix, Qt 6 reads a serial port when the port's read QSocketNotifier (a child of the
// port) receives QEvent::SockAct; readyRead and the reader run inside that event. The
// sniffer filters that event, opens a QIODevice read transaction around it, and afterwards
// rolls the transaction back and reads exactly the bytes the reader consumed (bytes the
// reader left stay for it). Measured with Qt 6.4.2 on Linux.
//
// Where the port has no such notifier (another platform or Qt version) attach() returns
// false and nothing is reported; callers must work without raw bytes then.
// The port closes and re-creates its notifier on every open: call attach() after each.
// bytesRead() is emitted synchronously from inside the port's read handling: receivers
// must only record the bytes (never close or reopen the port there).
class SerialReadSniffer : public QObject
{
    Q_OBJECT
public:
    explicit SerialReadSniffer(QObject *parent = nullptr);
    ~SerialReadSniffer() override;

    bool attach(QIODevice *device);
    void detach();
    bool isActive() const { return m_notifier && m_device; }
    quint64 bytesSeen() const { return m_bytesSeen; }

signals:
    void bytesRead(const QByteArray &bytes);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    QPointer<QIODevice> m_device;
    QPointer<QSocketNotifier> m_notifier;
    quint64 m_bytesSeen = 0;
};

} // namespace dd
