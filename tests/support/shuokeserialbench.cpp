#include "tests/support/shuokeserialbench.h"

#include "core/drive/driveconnection.h"
#include "core/drive/drivereply.h"
#include "core/drive/shuoke/shuokebackend.h"
#include "core/drive/shuoke/shuokedrive.h"
#include "core/link/traffictap.h"
#include "sim/bus/ptyendpoint.h"
#include "sim/bus/simserialbus.h"
#include "tests/support/replywait.h"

namespace dd {

ShuokeSerialBench::ShuokeSerialBench(QObject *parent)
    : QObject(parent)
{
}

ShuokeSerialBench::~ShuokeSerialBench()
{
    m_connection.reset();
    m_bus.reset();
}

bool ShuokeSerialBench::start(QString *error)
{
    if (!PtyEndpoint::isSupported()) {
        if (error)
            *error = QStringLiteral("pseudo-terminals are not supported here");
        return false;
    }
    auto *pty = new PtyEndpoint;
    const Error e = pty->open();
    if (e) {
        delete pty;
        if (error)
            *error = e.message;
        return false;
    }
    m_port = pty->clientPath();
    m_bus = std::make_unique<SimSerialBus>(pty);
    return true;
}

SimShuokeSerialDevice *ShuokeSerialBench::addDrive(const SimShuokeDrive::Config &config,
                                                   SimShuokeSerialDevice::Framing framing, shuoke::AsciiCheck check)
{
    auto device = std::make_unique<SimShuokeSerialDevice>(config, framing, check);
    SimShuokeSerialDevice *raw = device.get();
    SimSerialBus *bus = m_bus.get();
    raw->setClock([bus] { return bus->nowUs(); });
    m_bus->addDevice(std::move(device));
    return raw;
}

bool ShuokeSerialBench::connectHost(ConnectionSettings settings, QString *error)
{
    settings.family = Family::Shuoke;
    settings.port = m_port;
    m_connection = std::make_unique<DriveConnection>();
    connect(m_connection->tap(), &TrafficTap::frameRecorded, this,
            [this](const TrafficRecord &r) { m_records.append(r); });
    Error e;
    if (!m_connection->open(settings, &e)) {
        if (error)
            *error = e.message;
        return false;
    }
    return true;
}

ShuokeBackend *ShuokeSerialBench::backend() const
{
    return m_connection ? qobject_cast<ShuokeBackend *>(m_connection->backend()) : nullptr;
}

ShuokeDrive *ShuokeSerialBench::drive(int address) const
{
    return backend() ? backend()->shuokeDrive(address) : nullptr;
}

QString ShuokeSerialBench::portPath() const
{
    return m_port;
}

int ShuokeSerialBench::txCount() const
{
    int n = 0;
    for (const TrafficRecord &r : m_records)
        if (r.direction == TrafficRecord::Direction::Tx)
            ++n;
    return n;
}

bool ShuokeSerialBench::wait(DriveReply *reply, int timeoutMs)
{
    return test::waitForReply(reply, timeoutMs);
}

} // namespace dd
