#pragma once

#include "core/link/wiretime.h"
#include "sim/bus/faultinjector.h"

#include <QByteArray>
#include <QList>
#include <QString>

namespace dd {

// A simulated drive on a multi-drop serial bus (RS485 / RS232), as SimSerialBus drives it.
// The family simulators (servo-modbus, shuoke RTU / ASCII / PLC) implement this.
//
// What the bus does, so that an implementation does not have to:
//   - Timing. The bus paces everything with the wire-timing model (WireTime, 10 bits per
//     character unless bitsPerChar() says otherwise): a chunk from the host is delivered at
//     the time its last byte would have arrived; each reply leaves latencyUs() (plus any
//     injected extra latency) later, once the half-duplex line is free, and is written to
//     the host whole when its last byte would have arrived. Implementations never sleep,
//     never start timers for replies and never look at a wall clock.
//   - Baud rate. When the host's configured baud (if the endpoint knows it) differs from
//     baud(), the device is handed what its UART would make of the bytes
//     (UartResampler): garbage, usually of a different length. Its replies, if any, are
//     garbled the same way on their way to the host (a chunk its UART hears as nothing at
//     all is not delivered). baud() is read for every chunk, so a
//     drive may change it at run time (after a "set baud" command, or the Shuoke rule
//     "9600 for the first 2 s after power-up").
//   - Faults. faults() belongs to the device; the bus applies it to each reply frame:
//     drop, corrupt (one bit), extra latency, and silent (power loss: the device is handed
//     no bytes at all and nothing it returns is sent).
//   - Collisions. If two or more devices answer the same chunk (a broadcast query on a
//     multi-drop line), their replies overlap on the wire and the host receives garbage
//     (SimSerialBus::setCollisionsModelled).
//
// What the implementation does:
//   - onBusBytes() sees every byte the host sends, including requests for other addresses
//     (the other simulated drives' replies are not included). Chunks carry no framing: a frame
//     may come in pieces or several frames in one chunk. Keep a receive buffer, frame by
//     structure and / or by silence (`nowUs` gaps longer than WireTime::modbusSilenceUs()),
//     resynchronise after garbage, and never read past the buffer.
//   - Return the complete reply frames to send for what has just been completed (empty
//     list: no reply, e.g. broadcast, wrong address, bad CRC). Several frames are sent back
//     to back in order.
//   - advanceTo(nowUs) brings the drive's motor model to the bus time; the bus calls it
//     before every onBusBytes() (and an implementation may call it from its own getters).
//
// Times are microseconds of the bus's monotonic clock (SimSerialBus::nowUs()), starting near
// zero when the bus is created. `nowUs` may lie slightly in the future of the wall clock,
// because it is the modelled arrival time of the chunk's last byte.
class SimSerialDevice
{
public:
    static constexpr qint64 DefaultLatencyUs = 1000; // typical servo drive turnaround

    SimSerialDevice() = default;
    virtual ~SimSerialDevice() = default;
    SimSerialDevice(const SimSerialDevice &) = delete;
    SimSerialDevice &operator=(const SimSerialDevice &) = delete;

    virtual QList<QByteArray> onBusBytes(const QByteArray &bytes, qint64 nowUs) = 0;
    virtual int baud() const = 0;
    virtual QString describe() const = 0; // one line, e.g. "servo-modbus addr 1 @ 19200"
    virtual void advanceTo(qint64 nowUs) = 0;
    virtual int bitsPerChar() const { return WireTime::DefaultBitsPerChar; }

    // Processing time from the end of a request to the start of the reply.
    qint64 latencyUs() const { return m_latencyUs; }
    void setLatencyUs(qint64 us) { m_latencyUs = us < 0 ? 0 : us; }

    FaultInjector &faults() { return m_faults; }
    const FaultInjector &faults() const { return m_faults; }

private:
    FaultInjector m_faults;
    qint64 m_latencyUs = DefaultLatencyUs;
};

} // namespace dd
