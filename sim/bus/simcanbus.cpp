#include "sim/bus/simcanbus.h"

#include "core/link/wiretime.h"
#include "sim/bus/simlogging.h"

#include <QCanBus>
#include <QCanBusDevice>
#include <QVariant>

#include <algorithm>
#include <cmath>

namespace dd {

namespace {
constexpr int MaxOutbox = 256;

QCanBusFrame toQt(const CanFrameData &f)
{
    QCanBusFrame frame(f.id, f.data.left(8));
    frame.setExtendedFrameFormat(f.extended);
    return frame;
}
} // namespace

SimCanBus::SimCanBus(QObject *parent)
    : QObject(parent)
    , m_busTimer(this)
{
    m_clock.start();
    m_tickTimer.setInterval(TickIntervalMs);
    m_tickTimer.setTimerType(Qt::PreciseTimer);
    connect(&m_tickTimer, &QTimer::timeout, this, &SimCanBus::onTick);
    connect(&m_busTimer, &MicroTimer::timeout, this, &SimCanBus::pump);
}

SimCanBus::~SimCanBus()
{
    m_tickTimer.stop();
    m_busTimer.stop();
    if (m_device) {
        disconnect(m_device, nullptr, this, nullptr);
        m_device->disconnectDevice();
        delete m_device;
    }
}

Error SimCanBus::open(const QString &plugin, const QString &interfaceName, int bitrate, bool configureBitrate)
{
    if (m_device)
        return {ErrorCode::Busy, tr("The simulated CAN bus %1 is already open.").arg(description())};
    QString errorString;
    QCanBusDevice *dev = QCanBus::instance()->createDevice(plugin, interfaceName, &errorString);
    if (!dev) {
        return {ErrorCode::OpenFailed,
                tr("Cannot create the CAN interface %1:%2 (%3). Is the plugin installed?")
                    .arg(plugin, interfaceName, errorString.isEmpty() ? tr("unknown plugin") : errorString)};
    }
    if (plugin == QLatin1String("socketcan")) {
        // Qt would configure the bitrate itself (privileges, libsocketcan): use the
        // interface as the system configured it unless told otherwise.
        dev->setConfigurationParameter(QCanBusDevice::BitRateKey,
                                       configureBitrate ? QVariant(bitrate > 0 ? bitrate : DefaultBitrate)
                                                        : QVariant());
    } else if (plugin != QLatin1String("virtualcan") || configureBitrate) {
        dev->setConfigurationParameter(QCanBusDevice::BitRateKey, bitrate > 0 ? bitrate : DefaultBitrate);
    }
    return open(dev, plugin, interfaceName, bitrate);
}

Error SimCanBus::open(QCanBusDevice *dev, const QString &plugin, const QString &interfaceName, int bitrate)
{
    if (!dev)
        return {ErrorCode::InvalidArgument, tr("No CAN device to open the simulated bus on.")};
    if (m_device) {
        delete dev;
        return {ErrorCode::Busy, tr("The simulated CAN bus %1 is already open.").arg(description())};
    }
    setBitrate(bitrate);
    m_plugin = plugin;
    m_interface = interfaceName;
    dev->setParent(this);
    m_device = dev;
    dev->setConfigurationParameter(QCanBusDevice::ReceiveOwnKey, false);

    connect(dev, &QCanBusDevice::framesReceived, this, &SimCanBus::onFramesReceived);
    connect(dev, &QCanBusDevice::stateChanged, this,
            [this](QCanBusDevice::CanBusDeviceState s) { onStateChanged(static_cast<int>(s)); });
    connect(dev, &QCanBusDevice::errorOccurred, this,
            [this](QCanBusDevice::CanBusError e) { onDeviceError(static_cast<int>(e)); });

    if (!dev->connectDevice()) {
        const QString why = dev->errorString();
        disconnect(dev, nullptr, this, nullptr);
        m_device = nullptr;
        delete dev;
        return {ErrorCode::OpenFailed,
                tr("Cannot connect to the CAN interface %1:%2 (%3).").arg(plugin, interfaceName, why)};
    }
    qCDebug(lcSim).noquote() << "CAN bus opening:" << description();
    // Some plugins (virtualcan when its TCP server is unreachable) stay in ConnectingState
    // without an error: say so instead of waiting silently.
    QTimer::singleShot(ConnectTimeoutMs, dev, [this, dev] {
        if (m_device == dev && dev->state() != QCanBusDevice::ConnectedState) {
            const QString message = tr("%1: not connected after %2 s.").arg(description()).arg(ConnectTimeoutMs / 1000);
            qCWarning(lcSim).noquote() << message;
            emit errorOccurred(message);
        }
    });
    if (dev->state() == QCanBusDevice::ConnectedState)
        onStateChanged(static_cast<int>(QCanBusDevice::ConnectedState));
    return Error::none();
}

void SimCanBus::close()
{
    m_tickTimer.stop();
    m_busTimer.stop();
    m_ready.clear();
    m_onBus.reset();
    m_outbox.clear();
    if (!m_device)
        return;
    QCanBusDevice *dev = m_device;
    m_device = nullptr;
    disconnect(dev, nullptr, this, nullptr);
    dev->disconnectDevice();
    dev->deleteLater();
    if (m_wasConnected) {
        m_wasConnected = false;
        emit disconnected();
    }
}

bool SimCanBus::isOpen() const
{
    return !m_device.isNull();
}

bool SimCanBus::isConnected() const
{
    return m_device && m_device->state() == QCanBusDevice::ConnectedState;
}

QString SimCanBus::description() const
{
    return tr("%1:%2 @ %3 kbit/s").arg(m_plugin, m_interface).arg(m_bitrate / 1000);
}

void SimCanBus::setBitrate(int bitsPerSecond)
{
    m_bitrate = bitsPerSecond > 0 ? bitsPerSecond : DefaultBitrate;
}

SimCanDevice *SimCanBus::addDevice(std::unique_ptr<SimCanDevice> device)
{
    if (!device)
        return nullptr;
    m_devices.push_back(std::move(device));
    return m_devices.back().get();
}

SimCanDevice *SimCanBus::device(int index) const
{
    if (index < 0 || index >= deviceCount())
        return nullptr;
    return m_devices[static_cast<size_t>(index)].get();
}

qint64 SimCanBus::nowUs() const
{
    return m_clock.nsecsElapsed() / 1000;
}

int SimCanBus::pendingFrames() const
{
    return static_cast<int>(m_ready.size()) + (m_onBus ? 1 : 0);
}

qint64 SimCanBus::frameUs(const CanFrameData &frame) const
{
    const double us = WireTime::canFrameUs(static_cast<int>(frame.data.size()), frame.extended, m_bitrate,
                                           CanStuffing::WorstCase);
    return static_cast<qint64>(std::ceil(us - 1e-9));
}

void SimCanBus::onStateChanged(int state)
{
    if (state == QCanBusDevice::ConnectedState) {
        if (m_wasConnected)
            return;
        m_wasConnected = true;
        qCDebug(lcSim).noquote() << "CAN bus connected:" << description();
        const QList<QCanBusFrame> queued = std::exchange(m_outbox, {});
        for (const QCanBusFrame &f : queued) {
            if (!m_device || !m_device->writeFrame(f))
                ++m_stats.writeFailures;
        }
        m_tickTimer.start();
        emit connected();
    } else if (state == QCanBusDevice::UnconnectedState && m_wasConnected) {
        m_wasConnected = false;
        // The drives live on without the bus (their watchdogs trip, motors coast to rest):
        // keep ticking; what they send waits in the bounded outbox.
        qCWarning(lcSim).noquote() << "CAN bus disconnected:" << description();
        emit disconnected();
    }
}

void SimCanBus::onDeviceError(int error)
{
    if (error == QCanBusDevice::NoError || !m_device)
        return;
    const QString message = QStringLiteral("%1: %2").arg(description(), m_device->errorString());
    qCWarning(lcSim).noquote() << "CAN error" << error << message;
    emit errorOccurred(message);
}

void SimCanBus::onFramesReceived()
{
    if (!m_device)
        return;
    const QList<QCanBusFrame> frames = m_device->readAllFrames();
    for (const QCanBusFrame &qf : frames) {
        if (qf.frameType() != QCanBusFrame::DataFrame || qf.hasFlexibleDataRateFormat() || qf.hasLocalEcho()
            || qf.payload().size() > 8) {
            ++m_stats.framesIgnored;
            continue;
        }
        const CanFrameData frame{qf.frameId(), qf.payload(), qf.hasExtendedFrameFormat()};
        const qint64 now = nowUs();
        // The bus went on while this thread slept: a frame that was ready when the bus freed
        // up went out then, ahead of this one, however late the timer that says so fires.
        advanceBus(now);
        ++m_stats.framesIn;
        emit frameReceived(frame, now);
        qCDebug(lcSimFrames).noquote() << "rx" << now << Qt::hex << frame.id << Qt::dec << frame.data.toHex(' ');

        const qint64 rxEnd = std::max(now, m_busFreeUs) + frameUs(frame);
        m_busFreeUs = rxEnd;
        for (int i = 0; i < deviceCount(); ++i) {
            SimCanDevice *dev = m_devices[static_cast<size_t>(i)].get();
            dev->advanceTo(rxEnd);
            if (dev->faults().isSilent()) {
                ++m_stats.silentDeliveries;
                continue;
            }
            const QList<CanFrameData> replies = dev->onCanFrame(frame, rxEnd);
            for (const CanFrameData &reply : replies)
                enqueue(reply, rxEnd + dev->latencyUs(), i);
        }
    }
    pump();
}

void SimCanBus::onTick()
{
    const qint64 now = nowUs();
    for (int i = 0; i < deviceCount(); ++i) {
        SimCanDevice *dev = m_devices[static_cast<size_t>(i)].get();
        dev->advanceTo(now);
        const QList<CanFrameData> frames = dev->tick(now);
        if (dev->faults().isSilent())
            continue;
        for (const CanFrameData &f : frames)
            enqueue(f, now, i);
    }
    pump();
}

// Applies the device's faults and queues the frame for the bus.
void SimCanBus::enqueue(const CanFrameData &frame, qint64 readyUs, int device)
{
    FaultInjector &faults = m_devices[static_cast<size_t>(device)]->faults();
    if (faults.dropNow()) {
        ++m_stats.framesDropped;
        return;
    }
    CanFrameData f = frame;
    f.data = faults.corrupt(f.data.left(8));
    if (faults.lastCorrupted())
        ++m_stats.framesCorrupted;
    const qint64 ready = readyUs + 1000 * static_cast<qint64>(faults.extraLatencyMs());
    m_ready.push_back(Queued{ready, m_seq++, f, device});
}

// Runs the bus model up to the present and arms the timer for its next event.
void SimCanBus::pump()
{
    const qint64 now = nowUs();
    advanceBus(now);
    armBusTimer(now);
}

// Runs the bus model up to `now`: finishes the frame on the bus, starts the next one
// (arbitration: lowest ID among those ready when the bus frees up), and so on. Frames start
// at the model's times, not when this thread gets to run.
void SimCanBus::advanceBus(qint64 now)
{
    for (;;) {
        if (m_onBus) {
            if (m_onBus->endUs > now)
                break;
            const OnBus done = *m_onBus;
            m_onBus.reset();
            transmit(done.frame, done.device, now);
            continue;
        }
        if (m_ready.empty())
            break;
        qint64 earliest = m_ready.front().readyUs;
        for (const Queued &q : m_ready)
            earliest = std::min(earliest, q.readyUs);
        const qint64 start = std::max(earliest, m_busFreeUs);
        if (start > now)
            break;
        auto winner = m_ready.end();
        for (auto it = m_ready.begin(); it != m_ready.end(); ++it) {
            if (it->readyUs > start)
                continue;
            if (winner == m_ready.end() || it->frame.id < winner->frame.id
                || (it->frame.id == winner->frame.id && it->seq < winner->seq))
                winner = it;
        }
        const qint64 end = start + frameUs(winner->frame);
        m_onBus = std::make_unique<OnBus>(OnBus{end, winner->frame, winner->device});
        m_busFreeUs = end;
        m_ready.erase(winner);
    }
}

// Arms the timer for the bus model's next event.
void SimCanBus::armBusTimer(qint64 now)
{
    qint64 next = -1;
    if (m_onBus) {
        next = m_onBus->endUs;
    } else if (!m_ready.empty()) {
        next = m_ready.front().readyUs;
        for (const Queued &q : m_ready)
            next = std::min(next, q.readyUs);
        next = std::max(next, m_busFreeUs);
    }
    if (next < 0) {
        m_busTimer.stop();
        return;
    }
    m_busTimer.start(next - now);
}

void SimCanBus::transmit(const CanFrameData &frame, int device, qint64 atUs)
{
    const QCanBusFrame qf = toQt(frame);
    if (!isConnected()) {
        if (m_outbox.size() >= MaxOutbox) {
            m_outbox.removeFirst();
            ++m_stats.writeFailures;
        }
        m_outbox.append(qf);
        return;
    }
    if (!m_device->writeFrame(qf)) {
        ++m_stats.writeFailures;
        qCWarning(lcSim).noquote() << "CAN write failed:" << m_device->errorString();
        return;
    }
    ++m_stats.framesOut;
    qCDebug(lcSimFrames).noquote() << "tx" << atUs << Qt::hex << frame.id << Qt::dec << frame.data.toHex(' ');
    emit frameSent(frame, atUs, device);
}

} // namespace dd
