#pragma once

#include "core/common/error.h"
#include "sim/bus/byteendpoint.h"

class QSocketNotifier;

namespace dd {

// A pseudo-terminal the host opens like a serial adapter: open() creates it and
// slavePath() (e.g. /dev/pts/7) is what the client (QSerialPort, mbpoll, ...) opens.
// This is the simulator's only POSIX code; on other systems open() fails with
// ErrorCode::NotSupported (isSupported() says so up front).
//
// Behaviour the host relies on:
//   - raw mode: no echo, no line editing, no CR/LF translation, 8-bit clean;
//   - the endpoint keeps a slave descriptor open itself, so a client may close and reopen
//     the port any number of times without the master seeing EIO / hang-up;
//   - hostBaud() reads the baud rate the client set (QSerialPort::setBaudRate sets the
//     pty's termios; a pty accepts any rate and simulates no timing: pacing is
//     SimSerialBus's job). Rates without a standard Bxxx constant report 0 (unknown);
//   - close() closes the master: the client sees the adapter vanish, which is how fault
//     tests unplug the adapter. Measured with Qt 6.4: the client's QSerialPort emits
//     errorOccurred(ReadError) ("No such file or directory"), not ResourceError, and stays
//     open: a host link must treat any read error as "adapter gone";
//   - bytes written while no client has the port open wait in the pty and are read by the
//     next client (as with some real adapters): a host link should clear() after open();
//   - an optional link path (open("/tmp/dd-servo")) is a symlink to the slave, created
//     atomically (an existing symlink there is replaced, anything else is an error) and
//     removed on close if it still points to this pty.
class PtyEndpoint : public ByteEndpoint
{
    Q_OBJECT
public:
    explicit PtyEndpoint(QObject *parent = nullptr);
    ~PtyEndpoint() override;

    static bool isSupported();

    // Creates the pty (and the symlink when `linkPath` is not empty).
    Error open(const QString &linkPath = QString());

    QString slavePath() const { return m_slavePath; }
    QString linkPath() const { return m_linkCreated ? m_linkPath : QString(); }
    // What a client should open: the link when there is one, else the slave path.
    QString clientPath() const { return m_linkCreated ? m_linkPath : m_slavePath; }
    // Bytes accepted by write() that the pty has not taken yet (its buffer was full).
    qint64 pendingBytes() const { return m_pending.size(); }

    bool isOpen() const override;
    qint64 write(const QByteArray &bytes) override;
    void close() override;
    QString description() const override;
    int hostBaud() const override;

private:
    void onReadable();
    void onWritable();
    bool flushPending();
    Error createLink(const QString &linkPath);
    void removeLink();

    int m_master = -1;
    int m_slave = -1;
    QSocketNotifier *m_readNotifier = nullptr;
    QSocketNotifier *m_writeNotifier = nullptr;
    QByteArray m_pending;
    QString m_slavePath;
    QString m_linkPath;
    bool m_linkCreated = false;
};

} // namespace dd
