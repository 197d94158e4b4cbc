#pragma once

#include "core/protocol/canframedata.h"
#include "sim/bus/faultinjector.h"

#include <QList>
#include <QString>

namespace dd {

// A simulated drive on a CAN bus, as SimCanBus drives it. The family simulators
// (servo-can, shuoke CAN) implement this.
//
// What the bus does, so that an implementation does not have to:
//   - Timing. Every frame occupies the bus for its bit time at the bus bitrate
//     (WireTime::canFrameUs, worst-case stuffing). A frame from the host is delivered at the
//     time its last bit would have passed; a reply becomes ready latencyUs() (plus injected
//     extra latency) later and is sent when the bus is free, i.e. written to the host when
//     its last bit would have passed. Frames ready at the same time go out lowest ID first
//     (arbitration). Implementations never sleep, never start timers, never read a clock.
//   - Periodic frames. tick() is called every SimCanBus::TickIntervalMs (5 ms) with the bus
//     time; return what is due by then (heartbeats every 30 ms, alarm repeats every 2 s,
//     an alarm frame right after the alarm appears, ...). Keep your own "next due" times
//     based on `nowUs`, so the cadence does not depend on the tick interval. Ticked frames
//     become ready at `nowUs` (no latency) and then wait for the bus like any frame.
//   - Faults. faults() belongs to the device; the bus applies drop / corrupt (one bit of
//     the data bytes) / extra latency to every frame it sends (replies and ticked frames)
//     and, when silent (power loss), hands the device no frames and sends nothing of it.
//     tick() and advanceTo() are still called while silent, so the motor keeps coasting.
//
// What the implementation does:
//   - onCanFrame() sees every data frame on the bus from the host (frames from the other
//     simulated drives are not included; remote and error frames are filtered out).
//     Ignore what is not addressed to you; return the frames to send in response (empty
//     list for none).
//   - advanceTo(nowUs) brings the motor model to the bus time; the bus calls it before
//     every onCanFrame() and tick().
//
// Times are microseconds of the bus's monotonic clock (SimCanBus::nowUs()), starting near
// zero when the bus is created.
class SimCanDevice
{
public:
    static constexpr qint64 DefaultLatencyUs = 200; // typical CAN drive turnaround

    SimCanDevice() = default;
    virtual ~SimCanDevice() = default;
    SimCanDevice(const SimCanDevice &) = delete;
    SimCanDevice &operator=(const SimCanDevice &) = delete;

    virtual QList<CanFrameData> onCanFrame(const CanFrameData &frame, qint64 nowUs) = 0;
    virtual QList<CanFrameData> tick(qint64 nowUs) = 0;
    virtual QString describe() const = 0; // one line, e.g. "servo-can station 3"
    virtual void advanceTo(qint64 nowUs) = 0;

    qint64 latencyUs() const { return m_latencyUs; }
    void setLatencyUs(qint64 us) { m_latencyUs = us < 0 ? 0 : us; }

    FaultInjector &faults() { return m_faults; }
    const FaultInjector &faults() const { return m_faults; }

private:
    FaultInjector m_faults;
    qint64 m_latencyUs = DefaultLatencyUs;
};

} // namespace dd
