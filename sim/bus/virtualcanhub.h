#pragma once

#include <QHash>
#include <QHostAddress>
#include <QList>
#include <QObject>
#include <QPointer>

class QCanBusDevice;
class QCanBusFrame;
class QTcpServer;
class QTcpSocket;

namespace dd {

class HubCanDevice;

// A stand-in for the TCP server inside Qt's virtualcan plugin, speaking its line protocol
// ("connect:can0", "can0:<id>#<flags>#<hex>", "disconnect:can0"; frames are forwarded as
// "<id>#<flags>#<hex>" to every other client on the same channel).
//
// Why: the plugin's own server and client sockets leave Nagle's algorithm on. A frame that
// follows an unacknowledged one then waits for the peer's delayed ACK — about 40 ms on Linux
// loopback — so pipelined requests (a 220-parameter backup: ~60 ms of bus time at 1 Mbit/s)
// stall and time out. Listening on the port before the first QCanBusDevice connects makes
// the plugin's server step aside ("port already in use": it does not start and its clients
// connect here); this hub sets TCP_NODELAY on every connection. Clients should do the same
// on their own socket (setLowDelay()).
//
// Use: start(port) before opening any virtualcan device on "tcp://127.0.0.1:<port>/canN";
// the hub must live as long as the bus. Devices on the hub may be opened from any thread
// (the simulator's and a DriveHub's I/O thread): see settlePluginServer().
class VirtualCanHub : public QObject
{
    Q_OBJECT
public:
    explicit VirtualCanHub(QObject *parent = nullptr);
    ~VirtualCanHub() override;

    // Listens on 127.0.0.1:port (0: any free port). Returns false if the port is taken.
    bool start(quint16 port = 0);
    quint16 port() const;
    // "tcp://127.0.0.1:<port>/can<channel>", the interface name for QCanBus::createDevice.
    QString interfaceName(int channel = 0) const;
    int clientCount() const { return static_cast<int>(m_clients.size()); }
    quint64 forwardedLines() const { return m_forwarded; }

    // Sets TCP_NODELAY on the plugin's socket inside `device` (a virtualcan QCanBusDevice,
    // or any object above it). Returns how many sockets were changed; 0 if none is found.
    static int setLowDelay(QObject *device);

    // Qt 6.4's virtualcan plugin asks its process-wide server object to start on every
    // connectDevice() to a loopback address. That object lives in the thread that first
    // did so; while it does not run (our hub holds the port), each later attempt from
    // another thread creates a QTcpServer child across threads ("QObject: Cannot create
    // children for a parent that is in a different thread (Parent is VirtualCanServer)"),
    // an unsynchronised write to the shared object. Once it runs it is left alone, so this
    // lets it run, once per process and from the calling thread, on a free loopback port
    // no device names (tcp://127.0.0.1:0). start() calls it. Consequence: in a process that
    // started a hub, the plugin never serves a port of its own (virtualcan:can0 then needs a
    // server elsewhere: a drivedesk-sim, or a hub on that port). Returns false if the
    // virtualcan plugin is missing.
    static bool settlePluginServer();

    // A CAN device on `channel` of this hub inside this process (HubCanDevice: no socket of
    // its own). Connect it like any QCanBusDevice; it must live in the hub's thread.
    QCanBusDevice *createLocalDevice(int channel, QObject *parent = nullptr);

    // HubCanDevice's side.
    void attachLocal(HubCanDevice *device);
    void detachLocal(HubCanDevice *device);
    void forwardFromLocal(HubCanDevice *from, const QCanBusFrame &frame);

private:
    void onNewConnection();
    void onReadyRead(QTcpSocket *socket);
    // Writes `line` to `to` if it listens on `channel` (true); keeps it for a client that
    // has not said which channel yet.
    bool sendLine(QTcpSocket *to, const QString &channel, const QByteArray &line);

    static constexpr int MaxEarlyLines = 1024;

    QTcpServer *m_server = nullptr;
    QList<QTcpSocket *> m_clients;
    QList<QPointer<HubCanDevice>> m_locals;
    QHash<QTcpSocket *, QList<std::pair<QString, QByteArray>>> m_early; // before "connect:"

    quint64 m_forwarded = 0;
};

} // namespace dd
