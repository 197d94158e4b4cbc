#pragma once

#include <QByteArray>
#include <QObject>
#include <QString>

namespace dd {

// The simulator's end of a byte stream to a host (a pty today; an in-process pipe for the
// portable demo bench later). SimSerialBus owns one and knows nothing else about it.
//
// Contract for implementations:
//   - received(bytes) is emitted from the event loop for every chunk the host wrote
//     (chunks carry no framing: a frame may arrive in pieces, or several frames in one);
//   - write() queues bytes for the host and never blocks; it returns the number of bytes
//     accepted (all of them, or -1 when the endpoint is closed or the data was refused);
//   - close() releases the endpoint so that the host side sees the adapter vanish; it emits
//     closed() once, as does any other way the endpoint stops working;
//   - hostBaud() is the baud rate the host configured on its side, when the endpoint can
//     know it (a pty can: the client's termios), else 0 = unknown.
class ByteEndpoint : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;
    ~ByteEndpoint() override = default;

    virtual bool isOpen() const = 0;
    virtual qint64 write(const QByteArray &bytes) = 0;
    virtual void close() = 0;
    // One line for logs and for the user, e.g. "pty /dev/pts/7 (link /tmp/dd-servo)".
    virtual QString description() const = 0;
    virtual int hostBaud() const { return 0; }

signals:
    void received(const QByteArray &bytes);
    void closed();
};

} // namespace dd
