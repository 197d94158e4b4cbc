#include "sim/bus/hubcandevice.h"

#include "sim/bus/virtualcanhub.h"

namespace dd {

HubCanDevice::HubCanDevice(VirtualCanHub *hub, int channel, QObject *parent)
    : QCanBusDevice(parent)
    , m_hub(hub)
    , m_channel(channel)
{
}

HubCanDevice::~HubCanDevice()
{
    if (m_hub)
        m_hub->detachLocal(this);
}

bool HubCanDevice::open()
{
    if (!m_hub || m_hub->port() == 0) {
        setError(tr("The virtual CAN hub is not running."), QCanBusDevice::ConnectionError);
        return false;
    }
    m_hub->attachLocal(this);
    setState(QCanBusDevice::ConnectedState);
    return true;
}

void HubCanDevice::close()
{
    if (m_hub)
        m_hub->detachLocal(this);
    setState(QCanBusDevice::UnconnectedState);
}

bool HubCanDevice::writeFrame(const QCanBusFrame &frame)
{
    if (state() != QCanBusDevice::ConnectedState || !m_hub) {
        setError(tr("The device is not connected to the virtual CAN hub."), QCanBusDevice::OperationError);
        return false;
    }
    if (!frame.isValid() || frame.hasFlexibleDataRateFormat()) {
        setError(tr("Only classic CAN frames can be sent on the virtual CAN hub."), QCanBusDevice::WriteError);
        return false;
    }
    m_hub->forwardFromLocal(this, frame);
    emit framesWritten(1);
    return true;
}

QString HubCanDevice::interpretErrorFrame(const QCanBusFrame &errorFrame)
{
    Q_UNUSED(errorFrame);
    return QString();
}

void HubCanDevice::deliver(const QCanBusFrame &frame)
{
    if (state() == QCanBusDevice::ConnectedState)
        enqueueReceivedFrames({frame});
}

} // namespace dd
