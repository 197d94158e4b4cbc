#pragma once

#include "core/common/microtimer.h"
#include "sim/bus/byteendpoint.h"
#include "sim/bus/simserialdevice.h"

#include <QElapsedTimer>
#include <QObject>

#include <memory>
#include <vector>

namespace dd {

// Diagnostics of a SimSerialBus (the drivedesk-sim status line, tests).
struct SimSerialBusStats
{
    quint64 chunksIn = 0; // chunks read from the endpoint
    quint64 bytesIn = 0;
    quint64 garbledDeliveries = 0; // chunks a device received at the wrong baud
    quint64 framesOut = 0;         // reply frames written to the host (a collision counts once)
    quint64 bytesOut = 0;
    quint64 framesDropped = 0; // by fault injection
    quint64 framesCorrupted = 0;
    quint64 silentDeliveries = 0; // chunks a silent (powered-off) device did not get
    quint64 collisions = 0;       // chunks answered by more than one device
};

// A simulated multi-drop serial line: one ByteEndpoint to the host, any number of
// SimSerialDevice drives on it. See simserialdevice.h for the timing, baud, fault and
// collision rules; in short, for a chunk of n bytes received at time `now`:
//   rxEnd    = max(now, lineFreeAt) + n · charTime(host baud)    (the line is half duplex)
//   device gets the chunk (garbled if its baud differs) at rxEnd
//   replyGo  = max(rxEnd + device latency + injected extra latency, lineFreeAt)
//   replyEnd = replyGo + replyBytes · charTime(device baud);  lineFreeAt = replyEnd
//   the reply is written to the host whole at replyEnd (MicroTimer: to the microsecond on
//   Linux, never earlier).
// When the endpoint cannot tell the host's baud (hostBaud() == 0) every device is assumed
// to match it.
class SimSerialBus : public QObject
{
    Q_OBJECT
public:
    // Takes ownership of `endpoint` (reparents it).
    explicit SimSerialBus(ByteEndpoint *endpoint, QObject *parent = nullptr);
    ~SimSerialBus() override;

    ByteEndpoint *endpoint() const { return m_endpoint; }

    // Adds a drive; the bus owns it. Returns it for convenience (nullptr if `device` is null).
    SimSerialDevice *addDevice(std::unique_ptr<SimSerialDevice> device);
    int deviceCount() const { return static_cast<int>(m_devices.size()); }
    SimSerialDevice *device(int index) const;

    // Overlapping replies of several devices to one chunk garble each other (default on,
    // as on a real RS485 line). Off: they are serialised like any other replies.
    void setCollisionsModelled(bool on) { m_collisions = on; }
    bool collisionsModelled() const { return m_collisions; }

    // Wire pacing (default on): replies take the wire time of request and reply at the baud
    // rate and the device's latency. Off: every reply is written at once, as a virtual
    // serial port, a TCP bridge or a Modbus slave simulator delivers it (faults' extra
    // latency still applies).
    void setWirePaced(bool on) { m_paced = on; }
    bool isWirePaced() const { return m_paced; }

    qint64 nowUs() const; // the bus clock (monotonic, µs)
    qint64 lineFreeAtUs() const { return m_lineFreeUs; }
    int pendingReplies() const { return static_cast<int>(m_pending.size()); }
    const SimSerialBusStats &stats() const { return m_stats; }
    void resetStats() { m_stats = {}; }

signals:
    // Diagnostics: every chunk from the host, and every reply as written (`device` is the
    // index of the sender, -1 for a collision of several).
    void bytesReceived(const QByteArray &bytes, qint64 atUs);
    void replyWritten(const QByteArray &bytes, qint64 atUs, int device);
    // The endpoint closed: pending replies were discarded.
    void endpointClosed();

private:
    struct Pending
    {
        qint64 dueUs;
        QByteArray bytes;
        int device;
    };

    void onReceived(const QByteArray &bytes);
    void onEndpointClosed();
    void onTimer();
    void schedule(qint64 readyUs, qint64 durationUs, const QByteArray &bytes, int device);
    void arm();

    ByteEndpoint *m_endpoint = nullptr;
    std::vector<std::unique_ptr<SimSerialDevice>> m_devices;
    std::vector<Pending> m_pending; // sorted by dueUs
    QElapsedTimer m_clock;
    MicroTimer m_timer;
    qint64 m_lineFreeUs = 0;
    bool m_collisions = true;
    bool m_paced = true;
    SimSerialBusStats m_stats;
};

} // namespace dd
