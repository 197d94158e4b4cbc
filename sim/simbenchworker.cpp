#include "simbenchworker.h"

#include "ptyendpoint.h"
#include "simcanbus.h"
#include "simserialbus.h"
#include "simservocandrive.h"
#include "simservomodbusdrive.h"
#include "virtualcanhub.h"

namespace dd {

SimBenchWorker::SimBenchWorker(QObject *parent)
    : QObject(parent)
{
}

SimBenchWorker::~SimBenchWorker()
{
    // The CAN bus before the hub it is connected to; the serial buses close their ptys.
    delete m_canBus;
    delete m_canHub;
    qDeleteAll(m_serialBuses);
}

Error SimBenchWorker::build(int address)
{
    if (!PtyEndpoint::isSupported())
        return {ErrorCode::NotSupported,
                tr("The demo bench needs pseudo-terminals, which this system does not offer.")};

    // servo-modbus on a pty.
    auto *pty = new PtyEndpoint;
    if (Error e = pty->open()) {
        delete pty;
        return e;
    }
    auto *modbusBus = new SimSerialBus(pty);
    m_serialBuses.append(modbusBus);
    SimServoModbusDrive::Config mc;
    mc.address = address;
    auto *modbus = static_cast<SimServoModbusDrive *>(
        modbusBus->addDevice(std::make_unique<SimServoModbusDrive>(mc)));
    ConnectionSettings ms;
    ms.family = Family::ServoModbus;
    ms.port = pty->clientPath();
    ms.baud = modbus->baud();
    m_connections.append(ms);
    m_descriptions.append(QStringLiteral("%1 on %2").arg(modbus->describe(), pty->description()));

    if (Error e = addCanBus(address))
        return e;
    return Error::none();
}

Error SimBenchWorker::addCanBus(int station)
{
    // A private virtualcan server on a free port: never shared with another bench or test.
    // The hub (not the plugin's own server) so that TCP_NODELAY is set on every socket.
    m_canHub = new VirtualCanHub;
    if (!m_canHub->start(0))
        return {ErrorCode::OpenFailed, tr("The demo bench could not open a local port for its virtual CAN bus.")};
    m_canBus = new SimCanBus;
    auto *servo = static_cast<SimServoCanDrive *>(m_canBus->addDevice(std::make_unique<SimServoCanDrive>(station)));
    const QString iface = m_canHub->interfaceName(0);
    connect(m_canBus, &SimCanBus::connected, this, [this] {
        VirtualCanHub::setLowDelay(m_canBus->canDevice());
        emit ready();
    });
    connect(m_canBus, &SimCanBus::errorOccurred, this, [this](const QString &message) {
        if (!m_canBus->isConnected())
            emit failed({ErrorCode::OpenFailed, message});
    });
    if (Error e = m_canBus->open(QStringLiteral("virtualcan"), iface))
        return e;
    ConnectionSettings cs;
    cs.family = Family::ServoCan;
    cs.can = QStringLiteral("virtualcan:") + iface;
    cs.bitrate = m_canBus->bitrate();
    m_connections.append(cs);
    m_descriptions.append(QStringLiteral("%1 on %2").arg(servo->describe(), m_canBus->description()));
    return Error::none();
}

} // namespace dd
