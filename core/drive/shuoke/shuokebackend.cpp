#include "core/drive/shuoke/shuokebackend.h"

#include "core/drive/drivereply.h"
#include "core/drive/shuoke/shuokecantransport.h"
#include "core/drive/shuoke/shuokediscovery.h"
#include "core/drive/shuoke/shuokedrive.h"
#include "core/drive/shuoke/shuokeplctransport.h"
#include "core/drive/shuoke/shuokeserialtransport.h"
#include "core/link/connectionsettings.h"

namespace dd {

ShuokeBackend::ShuokeBackend(QObject *parent)
    : FamilyBackend(parent)
{
}

ShuokeBackend::~ShuokeBackend()
{
    dropTransport();
}

void ShuokeBackend::dropTransport()
{
    for (const QPointer<ShuokeDrive> &d : std::as_const(m_drives))
        delete d.data();
    m_drives.clear();
    if (m_transport) {
        m_transport->close();
        delete m_transport;
        m_transport = nullptr;
    }
    m_open = false;
}

bool ShuokeBackend::open(const ConnectionSettings &settings, TrafficTap *tap, Error *error)
{
    Error e;
    const ShuokeOptions options = ShuokeOptions::fromSettings(settings, &e);
    if (e) {
        if (error)
            *error = e;
        return false;
    }
    dropTransport();
    m_options = options;
    switch (options.framing) {
    case ShuokeFraming::Rtu:
    case ShuokeFraming::Ascii: m_transport = new ShuokeSerialTransport(options, this); break;
    case ShuokeFraming::Can: m_transport = new ShuokeCanTransport(options, this); break;
    case ShuokeFraming::Plc: m_transport = new ShuokePlcTransport(options, this); break;
    }
    if (!m_transport->open(settings, tap, &e)) {
        delete m_transport;
        m_transport = nullptr;
        if (error)
            *error = e;
        return false;
    }
    connect(m_transport, &ShuokeTransport::linkLost, this, [this](const Error &why) {
        const bool wasOpen = m_open;
        m_open = false;
        if (wasOpen)
            emit linkLost(why);
    });
    m_open = true;
    return true;
}

void ShuokeBackend::close()
{
    if (m_transport) {
        m_open = false;
        m_transport->close();
    }
}

bool ShuokeBackend::isOpen() const
{
    return m_open && m_transport;
}

Drive *ShuokeBackend::drive(int address)
{
    return shuokeDrive(address);
}

ShuokeDrive *ShuokeBackend::shuokeDrive(int address)
{
    if (!m_transport)
        return nullptr;
    const int highest = m_options.framing == ShuokeFraming::Can ? 250 : 247;
    if (address < 1 || address > highest)
        return nullptr;
    QPointer<ShuokeDrive> &d = m_drives[address];
    if (!d)
        d = new ShuokeDrive(m_transport, address, this);
    return d;
}

Discovery *ShuokeBackend::createDiscovery(const ScanOptions &options)
{
    return new ShuokeDiscovery(m_transport, options, this);
}

void ShuokeBackend::stopAll()
{
    if (!m_transport)
        return;
    if (m_options.framing != ShuokeFraming::Plc) {
        ShuokeRequest r;
        r.frame = shuoke::Frame::make(m_options.broadcast, shuoke::CmdEmergencyStop);
        r.expectReply = false;
        r.urgent = true;
        r.note = QStringLiteral("stop all (broadcast)");
        m_transport->request(r, this, [](const Error &, const shuoke::Frame &) {});
    }
    for (const QPointer<ShuokeDrive> &d : std::as_const(m_drives)) {
        if (!d)
            continue;
        DriveReply *r = d->stop(true);
        connect(r, &DriveReply::finished, r, &QObject::deleteLater);
    }
}

QString ShuokeBackend::linkDescription() const
{
    return m_transport ? m_transport->description() : QString();
}

} // namespace dd
