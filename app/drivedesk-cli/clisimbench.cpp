#include "clisimbench.h"

#include "ptyendpoint.h"
#include "simcanbus.h"
#include "simserialbus.h"
#include "simservocandrive.h"
#include "simservomodbusdrive.h"
#include "virtualcanhub.h"

namespace dd {

CliSimBench::CliSimBench(QObject *parent)
    : QObject(parent)
{
}

CliSimBench::~CliSimBench()
{
    // The buses before the hub they are connected to.
    delete m_can;
    delete m_serial;
    delete m_hub;
}

int CliSimBench::defaultBaud(Family family)
{
    switch (family) {
    case Family::ServoModbus: return 19200;
    case Family::Shuoke: return 9600;
    case Family::ServoCan: break;
    }
    return 0;
}

Error CliSimBench::start(CliGlobals *globals)
{
    if (globals->simDrives.isEmpty())
        globals->simDrives.append({globals->address, globals->connection.baud});
    const Family f = globals->connection.family;
    const bool can = f == Family::ServoCan || (f == Family::Shuoke && globals->connection.framing == QLatin1String("can"));
    return can ? startCan(globals) : startSerial(globals);
}

Error CliSimBench::startSerial(CliGlobals *globals)
{
    ConnectionSettings &c = globals->connection;
    if (!PtyEndpoint::isSupported())
        return {ErrorCode::NotSupported, tr("The serial simulator needs pseudo-terminals, which this system lacks.")};
    auto *endpoint = new PtyEndpoint;
    if (Error e = endpoint->open()) {
        delete endpoint;
        return {ErrorCode::OpenFailed, tr("Could not start the simulated serial bus: %1").arg(e.message)};
    }
    m_serial = new SimSerialBus(endpoint, this);
    QStringList drives;
    for (const CliGlobals::SimDrive &d : std::as_const(globals->simDrives)) {
        const int baud = d.baud ? d.baud : c.baud ? c.baud : defaultBaud(c.family);
        switch (c.family) {
        case Family::ServoModbus: {
            SimServoModbusDrive::Config config;
            config.address = d.address;
            config.baud = baud;
            m_serial->addDevice(std::make_unique<SimServoModbusDrive>(config));
            break;
        }
        case Family::Shuoke:
            return {ErrorCode::NotSupported, tr("This build has no shuoke simulator.")};
        case Family::ServoCan:
            return {ErrorCode::NotSupported, tr("servo-can drives are on CAN.")};
        }
        drives << tr("address %1 at %2 baud").arg(d.address).arg(baud);
    }
    c.port = endpoint->clientPath();
    m_description = tr("simulated %1 bus on %2: %3")
                        .arg(familyId(c.family), c.port, drives.join(QLatin1String(", ")));
    return {};
}

Error CliSimBench::startCan(CliGlobals *globals)
{
    ConnectionSettings &c = globals->connection;
    m_hub = new VirtualCanHub;
    if (!m_hub->start(0))
        return {ErrorCode::OpenFailed, tr("Could not start the simulated CAN bus (no free local TCP port).")};
    m_can = new SimCanBus;
    const int bitrate = c.bitrate ? c.bitrate : SimCanBus::DefaultBitrate;
    if (Error e = m_can->open(QStringLiteral("virtualcan"), m_hub->interfaceName(0), bitrate))
        return {ErrorCode::OpenFailed, tr("Could not start the simulated CAN bus: %1").arg(e.message)};
    QStringList drives;
    for (const CliGlobals::SimDrive &d : std::as_const(globals->simDrives)) {
        if (c.family != Family::ServoCan)
            return {ErrorCode::NotSupported, tr("This build has no %1 CAN simulator.").arg(familyId(c.family))};
        if (d.address > 99)
            return {ErrorCode::InvalidArgument, tr("--sim-drives: servo-can stations are 0 to 99.")};
        m_can->addDevice(std::make_unique<SimServoCanDrive>(d.address));
        drives << tr("station %1").arg(d.address);
    }
    c.can = QStringLiteral("virtualcan:") + m_hub->interfaceName(0);
    c.port.clear();
    m_description = tr("simulated %1 bus on %2: %3")
                        .arg(familyId(c.family), c.can, drives.join(QLatin1String(", ")));
    return {};
}

} // namespace dd
