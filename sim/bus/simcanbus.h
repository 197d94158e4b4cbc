#pragma once

#include "core/common/error.h"
#include "core/common/microtimer.h"
#include "sim/bus/simcandevice.h"

#include <QCanBusDevice>
#include <QCanBusFrame>
#include <QElapsedTimer>
#include <QObject>
#include <QPointer>
#include <QTimer>

#include <memory>
#include <vector>

namespace dd {

// Diagnostics of a SimCanBus.
struct SimCanBusStats
{
    quint64 framesIn = 0;      // data frames from the host
    quint64 framesIgnored = 0; // remote, error, CAN FD and echoed frames
    quint64 framesOut = 0;     // frames written to the bus
    quint64 framesDropped = 0; // by fault injection
    quint64 framesCorrupted = 0;
    quint64 silentDeliveries = 0; // frames a silent (powered-off) device did not get
    quint64 writeFailures = 0;    // writeFrame() refused, or queue overflow before connecting
};

// A simulated CAN bus: one QCanBusDevice (any Qt CAN plugin: virtualcan for tests and the
// demo, socketcan on machines that have it) and any number of SimCanDevice drives behind
// it. See simcandevice.h for what a drive implementation gets. The bus model:
//   - every frame, received or sent, occupies the bus for WireTime::canFrameUs(dlc,
//     extended, bitrate(), CanStuffing::WorstCase); `busFreeAt` is when the last one ends;
//   - a host frame received at `now` is taken to occupy [max(now, busFreeAt), rxEnd] and is
//     handed to every device at rxEnd;
//   - a device frame becomes ready at rxEnd + latency + injected latency (ticked frames: at
//     the tick time + injected latency); when the bus is free the lowest ID among the ready
//     frames wins, occupies the bus for its bit time and is written when its bits end (a
//     MicroTimer: to the microsecond on Linux, never earlier; late wake-ups catch up on
//     the modelled timeline).
// With nothing else on the bus a reply thus leaves at rxEnd + latency, the issue's
// "max(now, busFreeAt) + latency", and arrives one frame time later.
//
// Plugin notes (see docs/qt-notes.md): connectDevice() is asynchronous: frames produced before
// ConnectedState are queued and flushed on connection. virtualcan ignores the bitrate and
// offers can0 / can1 only ("tcp://127.0.0.1:PORT/can1" selects another server port);
// socketcan would try to set the bitrate itself (root + libsocketcan), so unless
// `configureBitrate` is set the BitRateKey is cleared and the interface is used as
// configured (ip link set canX type can bitrate ...). bitrate() is then only the timing
// model's rate: keep it equal to the interface's.
class SimCanBus : public QObject
{
    Q_OBJECT
public:
    static constexpr int TickIntervalMs = 5;
    static constexpr int DefaultBitrate = 1000000;
    static constexpr int ConnectTimeoutMs = 5000; // errorOccurred() if still not connected

    explicit SimCanBus(QObject *parent = nullptr);
    ~SimCanBus() override;

    // Creates the device and starts connecting; connected() follows. Fails at once when the
    // plugin or interface cannot be created or connectDevice() refuses.
    Error open(const QString &plugin, const QString &interfaceName, int bitrate = DefaultBitrate,
               bool configureBitrate = false);
    // The same on a device made elsewhere (e.g. VirtualCanHub::createLocalDevice()); the bus
    // takes ownership, also when it fails. `plugin` and `interfaceName` name it in messages.
    Error open(QCanBusDevice *device, const QString &plugin, const QString &interfaceName,
               int bitrate = DefaultBitrate);
    void close();
    bool isOpen() const;         // a device exists (connecting or connected)
    bool isConnected() const;    // ConnectedState
    QString description() const; // "virtualcan:can1 @ 1000 kbit/s"
    QCanBusDevice *canDevice() const { return m_device; }

    int bitrate() const { return m_bitrate; }
    void setBitrate(int bitsPerSecond);

    // Adds a drive; the bus owns it. Returns it for convenience (nullptr if null).
    SimCanDevice *addDevice(std::unique_ptr<SimCanDevice> device);
    int deviceCount() const { return static_cast<int>(m_devices.size()); }
    SimCanDevice *device(int index) const;

    qint64 nowUs() const;
    qint64 busFreeAtUs() const { return m_busFreeUs; }
    int pendingFrames() const;
    const SimCanBusStats &stats() const { return m_stats; }
    void resetStats() { m_stats = {}; }

signals:
    void connected();
    void disconnected();
    // A technical message from the CAN plugin (also logged to drivedesk.sim).
    void errorOccurred(const QString &message);
    // Diagnostics: host frames as received, device frames as written (`device` = index).
    void frameReceived(const dd::CanFrameData &frame, qint64 atUs);
    void frameSent(const dd::CanFrameData &frame, qint64 atUs, int device);

private:
    struct Queued
    {
        qint64 readyUs;
        quint64 seq;
        CanFrameData frame;
        int device;
    };
    struct OnBus
    {
        qint64 endUs;
        CanFrameData frame;
        int device;
    };

    void onFramesReceived();
    void onStateChanged(int state);
    void onDeviceError(int error);
    void onTick();
    void enqueue(const CanFrameData &frame, qint64 readyUs, int device);
    void pump();
    void advanceBus(qint64 now);
    void armBusTimer(qint64 now);
    void transmit(const CanFrameData &frame, int device, qint64 atUs);
    qint64 frameUs(const CanFrameData &frame) const;

    QPointer<QCanBusDevice> m_device;
    QString m_plugin;
    QString m_interface;
    int m_bitrate = DefaultBitrate;
    bool m_wasConnected = false;
    std::vector<std::unique_ptr<SimCanDevice>> m_devices;

    QElapsedTimer m_clock;
    QTimer m_tickTimer;
    MicroTimer m_busTimer;
    qint64 m_busFreeUs = 0;
    quint64 m_seq = 0;
    std::vector<Queued> m_ready;
    std::unique_ptr<OnBus> m_onBus;
    QList<QCanBusFrame> m_outbox; // written before ConnectedState
    SimCanBusStats m_stats;
};

} // namespace dd
