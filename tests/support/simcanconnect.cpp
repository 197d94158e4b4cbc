#include "tests/support/simcanconnect.h"

#include "sim/bus/simcanbus.h"
#include "sim/bus/virtualcanhub.h"

#include <QSignalSpy>

namespace dd::test {

QString connectSimCanBus(SimCanBus *bus, const QString &interfaceName)
{
    const Error e = bus->open(QStringLiteral("virtualcan"), interfaceName);
    if (e.isError())
        return e.message;
    QSignalSpy connected(bus, &SimCanBus::connected);
    if (!bus->isConnected() && !connected.wait(5000))
        return QStringLiteral("the simulated CAN bus did not connect within 5 s");
    VirtualCanHub::setLowDelay(bus->canDevice());
    return {};
}

} // namespace dd::test
