#include "tests/support/shuokeserialbench.h"

#include "core/drive/drivereply.h"
#include "sim/bus/ptyendpoint.h"
#include "sim/bus/simserialbus.h"
#include "tests/support/replywait.h"

namespace dd {

ShuokeSerialBench::ShuokeSerialBench(QObject *parent)
    : ShuokeHostBench(parent)
{
}

ShuokeSerialBench::~ShuokeSerialBench()
{
    closeHost();
    m_bus.reset();
}

std::unique_ptr<ShuokeSerialBench> ShuokeSerialBench::create(const QList<SimShuokeDrive::Config> &drives,
                                                             const ConnectionSettings &settings,
                                                             SimShuokeSerialDevice::Framing framing,
                                                             shuoke::AsciiCheck check)
{
    return createBench<ShuokeSerialBench>(drives, settings, framing, check);
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
    m_devices.append(raw);
    return raw;
}

bool ShuokeSerialBench::connectHost(ConnectionSettings settings, QString *error)
{
    settings.port = m_port;
    return openHost(settings, error);
}

QString ShuokeSerialBench::portPath() const
{
    return m_port;
}

bool ShuokeSerialBench::wait(DriveReply *reply, int timeoutMs)
{
    return test::waitForReply(reply, timeoutMs);
}

} // namespace dd
