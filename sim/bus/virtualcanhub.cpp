#include "sim/bus/virtualcanhub.h"

#include "sim/bus/hubcandevice.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QTcpServer>
#include <QTcpSocket>

#include <memory>
#include <mutex>

namespace dd {

namespace {
const char *kChannelsProperty = "dd_virtualcan_channels";

// The plugin's flags (qtserialbus, virtualcanbackend.cpp): remote, extended, FD, bitrate
// switch, error state, local echo.
constexpr char RemoteFlag = 'R';
constexpr char ExtendedFlag = 'X';
constexpr char FdFlag = 'F';
constexpr char BitrateSwitchFlag = 'B';
constexpr char ErrorStateFlag = 'E';
constexpr char LocalEchoFlag = 'L';

QString channelName(int channel)
{
    return QStringLiteral("can%1").arg(channel);
}

// "<id>#<flags>#<hex>\n", as a client receives a frame.
QByteArray frameLine(const QCanBusFrame &frame)
{
    QByteArray flags;
    if (frame.frameType() == QCanBusFrame::RemoteRequestFrame)
        flags.append(RemoteFlag);
    if (frame.hasExtendedFrameFormat())
        flags.append(ExtendedFlag);
    if (frame.hasFlexibleDataRateFormat())
        flags.append(FdFlag);
    if (frame.hasBitrateSwitch())
        flags.append(BitrateSwitchFlag);
    if (frame.hasErrorStateIndicator())
        flags.append(ErrorStateFlag);
    return QByteArray::number(frame.frameId()) + '#' + flags + '#' + frame.payload().toHex() + '\n';
}

// The frame in "<id>#<flags>#<hex>" (no channel, no newline); invalid if it is not one.
QCanBusFrame parseFrame(const QByteArray &text)
{
    const QByteArrayList parts = text.split('#');
    if (parts.size() != 3)
        return QCanBusFrame(QCanBusFrame::InvalidFrame);
    bool ok = false;
    const uint id = parts.at(0).toUInt(&ok);
    if (!ok)
        return QCanBusFrame(QCanBusFrame::InvalidFrame);
    const QByteArray &flags = parts.at(1);
    QCanBusFrame frame(id, QByteArray::fromHex(parts.at(2)));
    if (flags.contains(RemoteFlag))
        frame.setFrameType(QCanBusFrame::RemoteRequestFrame);
    frame.setExtendedFrameFormat(flags.contains(ExtendedFlag));
    frame.setFlexibleDataRateFormat(flags.contains(FdFlag));
    frame.setBitrateSwitch(flags.contains(BitrateSwitchFlag));
    frame.setErrorStateIndicator(flags.contains(ErrorStateFlag));
    frame.setLocalEcho(flags.contains(LocalEchoFlag));
    return frame;
}
} // namespace

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
            m_early.remove(s);
            s->deleteLater();
        });
    }
}

void VirtualCanHub::onReadyRead(QTcpSocket *from)
{
    QList<QTcpSocket *> touched;
    while (from->canReadLine()) {
        const QByteArray line = from->readLine().trimmed();
        if (line.startsWith("connect:")) {
            QStringList channels = from->property(kChannelsProperty).toStringList();
            const QString channel = QString::fromLatin1(line.mid(8));
            channels.append(channel);
            from->setProperty(kChannelsProperty, channels);
            // What the others sent on this channel while its "connect:" line was on the way
            // (the client counts as connected as soon as its socket is).
            for (const auto &[onChannel, early] : m_early.take(from)) {
                if (onChannel == channel) {
                    from->write(early);
                    if (!touched.contains(from))
                        touched.append(from);
                }
            }
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
            if (to == from || !sendLine(to, channel, frame))
                continue;
            if (!touched.contains(to))
                touched.append(to);
        }
        bool parsed = false;
        QCanBusFrame decoded;
        for (const QPointer<HubCanDevice> &local : std::as_const(m_locals)) {
            if (!local || channelName(local->channel()) != channel)
                continue;
            if (!parsed) {
                decoded = parseFrame(line.mid(colon + 1));
                parsed = true;
            }
            if (decoded.isValid()) {
                local->deliver(decoded);
                ++m_forwarded;
            }
        }
    }
    // Out now, one write per client for all the lines read (QTcpSocket would wait for the
    // next pass of the event loop).
    for (QTcpSocket *to : std::as_const(touched))
        to->flush();
}

bool VirtualCanHub::sendLine(QTcpSocket *to, const QString &channel, const QByteArray &line)
{
    const QVariant channels = to->property(kChannelsProperty);
    if (!channels.isValid()) {
        // Connected, its "connect:" line not read yet: keep the frame for it (bounded).
        QList<std::pair<QString, QByteArray>> &early = m_early[to];
        if (early.size() < MaxEarlyLines)
            early.append({channel, line});
        return false;
    }
    if (!channels.toStringList().contains(channel))
        return false;
    to->write(line);
    ++m_forwarded;
    return true;
}

void VirtualCanHub::attachLocal(HubCanDevice *device)
{
    if (device && !m_locals.contains(device))
        m_locals.append(device);
}

void VirtualCanHub::detachLocal(HubCanDevice *device)
{
    m_locals.removeAll(device);
}

void VirtualCanHub::forwardFromLocal(HubCanDevice *from, const QCanBusFrame &frame)
{
    const QString channel = channelName(from->channel());
    const QByteArray line = frameLine(frame);
    for (QTcpSocket *to : std::as_const(m_clients))
        if (sendLine(to, channel, line))
            to->flush();
    for (const QPointer<HubCanDevice> &local : std::as_const(m_locals)) {
        if (!local || local == from || local->channel() != from->channel())
            continue;
        local->deliver(frame);
        ++m_forwarded;
    }
}

QCanBusDevice *VirtualCanHub::createLocalDevice(int channel, QObject *parent)
{
    return new HubCanDevice(this, channel, parent);
}

} // namespace dd
