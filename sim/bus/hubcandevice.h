#pragma once

#include <QCanBusDevice>
#include <QPointer>

namespace dd {

class VirtualCanHub;

// A CAN device inside the process that runs a VirtualCanHub, attached to one of its
// channels directly: frames pass between the hub and this device as function calls, with
// no TCP socket and no text line on this side. The simulator's own bus uses it when it runs
// the hub itself (SimBench): each frame then crosses one loopback socket (client <-> hub)
// instead of two (client <-> hub <-> the simulator's virtualcan device), which halves the
// kernel's TCP work per frame on the simulator's thread (docs/performance.md, "The servo-can
// monitor: one socket hop"). Clients on the hub (virtualcan devices in this or another
// process) see no difference: the hub forwards this device's frames to them as lines.
//
// Lives in the hub's thread. Opening fails when the hub is gone or not started.
class HubCanDevice : public QCanBusDevice
{
    Q_OBJECT
public:
    HubCanDevice(VirtualCanHub *hub, int channel, QObject *parent = nullptr);
    ~HubCanDevice() override;

    int channel() const { return m_channel; }

    bool writeFrame(const QCanBusFrame &frame) override;
    QString interpretErrorFrame(const QCanBusFrame &errorFrame) override;

    // From the hub: a frame another client sent on this channel.
    void deliver(const QCanBusFrame &frame);

protected:
    bool open() override;
    void close() override;

private:
    QPointer<VirtualCanHub> m_hub;
    int m_channel = 0;
};

} // namespace dd
