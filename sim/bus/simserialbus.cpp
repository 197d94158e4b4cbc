#include "sim/bus/simserialbus.h"

#include "sim/bus/simlogging.h"
#include "sim/bus/uartresampler.h"

#include <algorithm>
#include <cmath>

namespace dd {

namespace {
qint64 ceilUs(double us)
{
    return static_cast<qint64>(std::ceil(us - 1e-9));
}

struct Candidate
{
    qint64 readyUs;
    qint64 durationUs;
    QByteArray bytes;
    int device;
};

// Overlapping transmissions on RS485 have no defined result; a receiver typically sees the
// bits of both mixed. Model: bitwise AND of the frames aligned at their start (a low level
// wins), as long as the longest one.
QByteArray collide(const QList<Candidate> &frames)
{
    QByteArray out;
    for (const Candidate &c : frames) {
        if (out.size() < c.bytes.size())
            out.append(QByteArray(c.bytes.size() - out.size(), '\xff'));
        for (qsizetype i = 0; i < c.bytes.size(); ++i)
            out[i] = static_cast<char>(static_cast<quint8>(out[i]) & static_cast<quint8>(c.bytes[i]));
    }
    return out;
}
} // namespace

SimSerialBus::SimSerialBus(ByteEndpoint *endpoint, QObject *parent)
    : QObject(parent)
    , m_endpoint(endpoint)
    , m_timer(this)
{
    m_clock.start();
    connect(&m_timer, &MicroTimer::timeout, this, &SimSerialBus::onTimer);
    // A reply's end on the wire is when the host may have it: write it on time.
    m_timer.setEarlyWakeUs(MicroTimer::WireTimeEarlyWakeUs);
    if (m_endpoint) {
        m_endpoint->setParent(this);
        connect(m_endpoint, &ByteEndpoint::received, this, &SimSerialBus::onReceived);
        connect(m_endpoint, &ByteEndpoint::closed, this, &SimSerialBus::onEndpointClosed);
    }
}

SimSerialBus::~SimSerialBus()
{
    m_timer.stop();
    if (m_endpoint)
        disconnect(m_endpoint, nullptr, this, nullptr);
}

SimSerialDevice *SimSerialBus::addDevice(std::unique_ptr<SimSerialDevice> device)
{
    if (!device)
        return nullptr;
    m_devices.push_back(std::move(device));
    return m_devices.back().get();
}

SimSerialDevice *SimSerialBus::device(int index) const
{
    if (index < 0 || index >= deviceCount())
        return nullptr;
    return m_devices[static_cast<size_t>(index)].get();
}

qint64 SimSerialBus::nowUs() const
{
    return m_clock.nsecsElapsed() / 1000;
}

void SimSerialBus::onReceived(const QByteArray &bytes)
{
    if (bytes.isEmpty())
        return;
    const qint64 now = nowUs();
    ++m_stats.chunksIn;
    m_stats.bytesIn += static_cast<quint64>(bytes.size());
    emit bytesReceived(bytes, now);
    qCDebug(lcSimFrames).noquote() << "rx" << now << bytes.toHex(' ');

    const int hostBaud = m_endpoint ? m_endpoint->hostBaud() : 0;
    const qint64 rxStart = m_paced ? std::max(now, m_lineFreeUs) : now;
    qint64 lineBusyUntil = hostBaud > 0 && m_paced ? rxStart + ceilUs(WireTime::serialBytesUs(bytes.size(), hostBaud))
                                                   : rxStart;
    QList<Candidate> candidates;
    int answeringDevices = 0;

    for (int i = 0; i < deviceCount(); ++i) {
        SimSerialDevice *dev = m_devices[static_cast<size_t>(i)].get();
        const int devBaud = dev->baud();
        const int bits = dev->bitsPerChar();
        const int lineBaud = hostBaud > 0 ? hostBaud : devBaud;
        const qint64 rxEnd = rxStart + (m_paced ? ceilUs(WireTime::serialBytesUs(bytes.size(), lineBaud, bits)) : 0);
        lineBusyUntil = std::max(lineBusyUntil, rxEnd);

        dev->advanceTo(rxEnd);
        if (dev->faults().isSilent()) {
            ++m_stats.silentDeliveries;
            continue;
        }
        const bool mismatch = lineBaud != devBaud;
        QByteArray heard = bytes;
        if (mismatch) {
            heard = UartResampler::resample(bytes, lineBaud, devBaud, bits);
            ++m_stats.garbledDeliveries;
        }
        const QList<QByteArray> replies = heard.isEmpty() ? QList<QByteArray>() : dev->onBusBytes(heard, rxEnd);
        bool answered = false;
        for (QByteArray reply : replies) {
            if (reply.isEmpty())
                continue;
            FaultInjector &faults = dev->faults();
            if (faults.dropNow()) {
                ++m_stats.framesDropped;
                qCDebug(lcSim).noquote() << dev->describe() << "reply dropped (fault injection)";
                continue;
            }
            reply = faults.corrupt(reply);
            if (faults.lastCorrupted())
                ++m_stats.framesCorrupted;
            const qint64 ready = rxEnd + (m_paced ? dev->latencyUs() : 0)
                + 1000 * static_cast<qint64>(faults.extraLatencyMs());
            const qint64 duration = m_paced ? ceilUs(WireTime::serialBytesUs(reply.size(), devBaud, bits)) : 0;
            if (mismatch)
                reply = UartResampler::resample(reply, devBaud, lineBaud, bits);
            candidates.append({ready, duration, reply, i});
            answered = true;
        }
        if (answered)
            ++answeringDevices;
    }
    m_lineFreeUs = std::max(m_lineFreeUs, lineBusyUntil);

    if (candidates.isEmpty())
        return;
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate &a, const Candidate &b) { return a.readyUs < b.readyUs; });

    if (m_collisions && answeringDevices > 1) {
        ++m_stats.collisions;
        qint64 duration = 0;
        for (const Candidate &c : std::as_const(candidates))
            duration = std::max(duration, c.durationUs);
        qCDebug(lcSim) << answeringDevices << "devices answered one chunk: collision";
        schedule(candidates.first().readyUs, duration, collide(candidates), -1);
        return;
    }
    for (const Candidate &c : std::as_const(candidates))
        schedule(c.readyUs, c.durationUs, c.bytes, c.device);
}

void SimSerialBus::schedule(qint64 readyUs, qint64 durationUs, const QByteArray &bytes, int device)
{
    const qint64 start = std::max(readyUs, m_lineFreeUs);
    const qint64 end = start + durationUs;
    m_lineFreeUs = end;
    // Kept sorted by due time; equal times stay in scheduling order.
    const auto pos = std::upper_bound(m_pending.begin(), m_pending.end(), end,
                                      [](qint64 due, const Pending &p) { return due < p.dueUs; });
    m_pending.insert(pos, Pending{end, bytes, device});
    arm();
}

void SimSerialBus::arm()
{
    if (m_pending.empty()) {
        m_timer.stop();
        return;
    }
    m_timer.start(m_pending.front().dueUs - nowUs());
}

void SimSerialBus::onTimer()
{
    const qint64 now = nowUs();
    while (!m_pending.empty() && m_pending.front().dueUs <= now) {
        const Pending p = m_pending.front();
        m_pending.erase(m_pending.begin());
        if (!m_endpoint || !m_endpoint->isOpen())
            continue;
        if (m_endpoint->write(p.bytes) < 0)
            continue;
        ++m_stats.framesOut;
        m_stats.bytesOut += static_cast<quint64>(p.bytes.size());
        qCDebug(lcSimFrames).noquote() << "tx" << now << p.bytes.toHex(' ');
        emit replyWritten(p.bytes, now, p.device);
    }
    arm();
}

void SimSerialBus::onEndpointClosed()
{
    m_pending.clear();
    m_timer.stop();
    emit endpointClosed();
}

} // namespace dd
