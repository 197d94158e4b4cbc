#include "sim/bus/virtualcanhub.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QTcpServer>
#include <QTcpSocket>

#include <memory>
#include <mutex>

namespace dd {

namespace {
const char *kChannelsProperty = "dd_virtualcan_channels";
}

VirtualCanHub::VirtualCanHub(QObject *parent)
    : QObject(parent)
{
}

VirtualCanHub::~VirtualCanHub()
{
    for (QTcpSocket *s : std::as_const(m_clients)) {
        s->disconnect(this);
        s->abort();
    }
}

bool VirtualCanHub::start(quint16 port)
{
    if (m_server)
        return true;
    settlePluginServer();
    auto *server = new QTcpServer(this);
    if (!server->listen(QHostAddress::LocalHost, port)) {
        delete server;
        return false;
    }
    m_server = server;
    connect(server, &QTcpServer::newConnection, this, &VirtualCanHub::onNewConnection);
    return true;
}

quint16 VirtualCanHub::port() const
{
    return m_server ? m_server->serverPort() : 0;
}

QString VirtualCanHub::interfaceName(int channel) const
{
    return QStringLiteral("tcp://127.0.0.1:%1/can%2").arg(port()).arg(channel);
}

int VirtualCanHub::setLowDelay(QObject *device)
{
    int n = 0;
    if (!device)
        return 0;
    for (QTcpSocket *s : device->findChildren<QTcpSocket *>()) {
        s->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        ++n;
    }
    return n;
}

bool VirtualCanHub::settlePluginServer()
{
    static std::once_flag once;
    static bool settled = false;
    std::call_once(once, [] {
        // Port 0: the plugin's server listens on a free port; the throw-away device's own
        // socket then fails to connect to port 0, and nothing else ever names that port.
        std::unique_ptr<QCanBusDevice> device(
            QCanBus::instance()->createDevice(QStringLiteral("virtualcan"), QStringLiteral("tcp://127.0.0.1:0/can0")));
        if (!device)
            return;
        device->connectDevice();
        settled = true;
    });
    return settled;
}

void VirtualCanHub::onNewConnection()
{
    while (QTcpSocket *s = m_server->nextPendingConnection()) {
        s->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        m_clients.append(s);
        connect(s, &QIODevice::readyRead, this, [this, s] { onReadyRead(s); });
        connect(s, &QTcpSocket::disconnected, this, [this, s] {
            m_clients.removeAll(s);
            s->deleteLater();
        });
    }
}

void VirtualCanHub::onReadyRead(QTcpSocket *from)
{
    while (from->canReadLine()) {
        const QByteArray line = from->readLine().trimmed();
        if (line.startsWith("connect:")) {
            QStringList channels = from->property(kChannelsProperty).toStringList();
            channels.append(QString::fromLatin1(line.mid(8)));
            from->setProperty(kChannelsProperty, channels);
            continue;
        }
        if (line.startsWith("disconnect:")) {
            QStringList channels = from->property(kChannelsProperty).toStringList();
            channels.removeAll(QString::fromLatin1(line.mid(11)));
            from->setProperty(kChannelsProperty, channels);
            from->disconnectFromHost();
            continue;
        }
        const qsizetype colon = line.indexOf(':');
        if (colon <= 0)
            continue; // not a frame line: ignore it, as the plugin's server would choke on it
        const QString channel = QString::fromLatin1(line.left(colon));
        const QByteArray frame = line.mid(colon + 1) + '\n';
        for (QTcpSocket *to : std::as_const(m_clients)) {
            if (to == from || !to->property(kChannelsProperty).toStringList().contains(channel))
                continue;
            to->write(frame);
            ++m_forwarded;
        }
    }
}

} // namespace dd
