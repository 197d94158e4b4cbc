#include "tests/support/shuokecanbench.h"

#include "core/drive/shuoke/shuokebackend.h"
#include "core/drive/shuoke/shuokecantransport.h"
#include "sim/bus/simcanbus.h"
#include "sim/bus/virtualcanhub.h"

#include <QCanBus>
#include <QDeadlineTimer>
#include <QLoggingCategory>
#include <QSignalSpy>

namespace dd {

ShuokeCanBench::ShuokeCanBench(QObject *parent)
    : ShuokeHostBench(parent)
{
}

ShuokeCanBench::~ShuokeCanBench()
{
    closeHost();
    m_bus.reset();
    m_hub.reset();
}

std::unique_ptr<ShuokeCanBench> ShuokeCanBench::create(const QList<SimShuokeDrive::Config> &drives,
                                                       const ConnectionSettings &settings)
{
    return createBench<ShuokeCanBench>(drives, settings);
}

bool ShuokeCanBench::start(QString *error)
{
    QLoggingCategory::setFilterRules(QStringLiteral("qt.canbus.plugins.virtualcan.info=false"));
    if (!QCanBus::instance()->plugins().contains(QLatin1String("virtualcan"))) {
        if (error)
            *error = QStringLiteral("Qt's virtualcan plugin is not installed");
        return false;
    }
    // A hub of our own on a free port (see virtualcanhub.h): no other process shares the
    // bus, and the plugin's sockets get TCP_NODELAY (pipelined requests do not stall).
    m_hub = std::make_unique<VirtualCanHub>();
    if (!m_hub->start()) {
        if (error)
            *error = QStringLiteral("the virtualcan hub could not listen");
        return false;
    }
    m_interface = m_hub->interfaceName(0);
    m_bus = std::make_unique<SimCanBus>();
    const Error e = m_bus->open(QStringLiteral("virtualcan"), m_interface, 100000);
    if (e) {
        if (error)
            *error = e.message;
        return false;
    }
    QSignalSpy connected(m_bus.get(), &SimCanBus::connected);
    if (!m_bus->isConnected() && !connected.wait(3000)) {
        if (error)
            *error = QStringLiteral("the simulated CAN bus did not connect");
        return false;
    }
    VirtualCanHub::setLowDelay(m_bus->canDevice());
    return true;
}

SimShuokeCanDevice *ShuokeCanBench::addDrive(const SimShuokeDrive::Config &config)
{
    auto device = std::make_unique<SimShuokeCanDevice>(config);
    SimShuokeCanDevice *raw = device.get();
    SimCanBus *bus = m_bus.get();
    raw->setClock([bus] { return bus->nowUs(); });
    m_bus->addDevice(std::move(device));
    m_devices.append(raw);
    return raw;
}

bool ShuokeCanBench::connectHost(ConnectionSettings settings, QString *error)
{
    settings.can = QStringLiteral("virtualcan:") + m_interface;
    if (!openHost(settings, error))
        return false;
    auto *can = qobject_cast<ShuokeCanTransport *>(backend()->transport());
    QDeadlineTimer deadline(3000);
    while (!can->link()->isConnected() && !deadline.hasExpired()) {
        QSignalSpy spy(can->link(), &CanLink::connected);
        spy.wait(100);
    }
    if (!can->link()->isConnected()) {
        if (error)
            *error = QStringLiteral("the host's CAN link did not connect");
        return false;
    }
    VirtualCanHub::setLowDelay(can->link());
    return true;
}

} // namespace dd
