#include "core/drive/shuoke/shuokediscovery.h"

#include "core/drive/shuoke/shuokecantransport.h"
#include "core/drive/shuoke/shuokeserialtransport.h"
#include "core/link/linkreply.h"
#include "core/link/seriallink.h"
#include "core/protocol/shuoke/shuokecan.h"
#include "core/protocol/shuoke/shuokecommands.h"

#include <cmath>
#include <memory>

namespace dd {

using shuoke::Frame;

ShuokeDiscovery::ShuokeDiscovery(ShuokeTransport *transport, const ScanOptions &options, QObject *parent)
    : Discovery(parent)
    , m_transport(transport)
    , m_options(options)
{
    m_listen.setSingleShot(true);
    connect(&m_listen, &QTimer::timeout, this, &ShuokeDiscovery::onListenDone);
}

ShuokeDiscovery::~ShuokeDiscovery()
{
    disconnect(m_canConnection);
}

int ShuokeDiscovery::baudCount() const
{
    return std::max<int>(1, static_cast<int>(m_bauds.size()));
}

int ShuokeDiscovery::probeTimeoutMs(int baud) const
{
    if (m_options.timeoutMs >= 0)
        return m_options.timeoutMs;
    // request + reply of a handshake (the longest: ASCII, 2 x 15 characters) at `baud`, plus
    // the drive's turnaround.
    const double wireMs = 2 * 15 * 10 * 1000.0 / std::max(baud, 1);
    return static_cast<int>(std::ceil(wireMs)) + 40;
}

void ShuokeDiscovery::start()
{
    if (m_running)
        return;
    m_running = true;
    m_cancelled = false;
    // A CAN bus may still be connecting (virtualcan connects asynchronously): its CanLink
    // queues the broadcast until then, and startCan() fails if the link is really closed.
    const bool can = m_transport && m_transport->framing() == ShuokeFraming::Can;
    if (!m_transport || (!can && !m_transport->isOpen())) {
        QTimer::singleShot(0, this, [this] { finish({ErrorCode::LinkClosed, tr("The link is not open.")}); });
        return;
    }
    if (m_transport->framing() == ShuokeFraming::Can) {
        startCan();
        return;
    }
    m_originalBaud = m_transport->baud();
    m_bauds = m_options.bauds;
    if (m_bauds.isEmpty() || m_transport->framing() == ShuokeFraming::Plc)
        m_bauds = {m_originalBaud};
    const int from = std::max(1, m_options.from);
    const int to = std::min(247, m_options.to);
    m_options.from = from;
    m_options.to = to;
    m_total = std::max(0, to - from + 1) * baudCount();
    m_baudIndex = 0;
    QTimer::singleShot(0, this, &ShuokeDiscovery::startBaud);
}

void ShuokeDiscovery::cancel()
{
    if (!m_running)
        return;
    m_cancelled = true;
    if (m_transport && m_transport->framing() == ShuokeFraming::Can) {
        m_listen.stop();
        finish({ErrorCode::Cancelled, tr("The scan was cancelled.")});
    }
    // Serial: the probe in flight finishes, then the scan stops.
}

void ShuokeDiscovery::finish(const Error &error)
{
    if (!m_running)
        return;
    m_running = false;
    disconnect(m_canConnection);
    m_listen.stop();
    if (m_transport && m_originalBaud > 0 && m_transport->baud() != m_originalBaud)
        m_transport->setBaud(m_originalBaud);
    emit finished(error);
}

void ShuokeDiscovery::report(int address)
{
    if (m_foundAtBaud.contains(address))
        return;
    m_foundAtBaud.insert(address);
    DiscoveredDrive d;
    d.family = Family::Shuoke;
    d.address = address;
    d.framing = shuokeFramingId(m_transport->framing());
    d.link = m_transport->description();
    if (m_transport->framing() == ShuokeFraming::Can)
        d.bitrate = static_cast<ShuokeCanTransport *>(m_transport.data())->bitrate();
    else
        d.baud = m_transport->baud();
    d.state = tr("answers");
    Discovery::report(d);
}

// --- CAN -----------------------------------------------------------------------------

void ShuokeDiscovery::startCan()
{
    auto *can = static_cast<ShuokeCanTransport *>(m_transport.data());
    m_total = 1;
    m_canConnection = connect(can->link(), &CanLink::frameReceived, this, &ShuokeDiscovery::onCanFrame);
    const Decoded<CanFrameData> frame = shuoke::encodeCan(
        Frame::make(m_transport->options().broadcast, shuoke::CmdQueryAddress), m_transport->options().can);
    if (!frame.ok() || !can->link()->send(*frame.value, QStringLiteral("scan: query address (broadcast)"))) {
        QTimer::singleShot(0, this, [this] {
            finish({ErrorCode::LinkClosed, tr("The query-address broadcast could not be sent.")});
        });
        return;
    }
    m_listen.start(std::max(10, m_options.listenMs));
}

void ShuokeDiscovery::onListenDone()
{
    emit progress(1, 1);
    finish(Error::none());
}

void ShuokeDiscovery::onCanFrame(const CanFrameData &frame)
{
    if (!m_running)
        return;
    const Decoded<Frame> f = shuoke::decodeCan(frame);
    if (!f.ok() || f.value->failure || f.value->command != shuoke::CmdQueryAddress)
        return;
    if (!shuoke::isUnicastAddress(f.value->address) && f.value->address > 250)
        return;
    if (f.value->address == 0)
        return;
    report(f.value->address);
}

// --- serial / PLC ----------------------------------------------------------------------

void ShuokeDiscovery::startBaud()
{
    if (m_cancelled) {
        finish({ErrorCode::Cancelled, tr("The scan was cancelled.")});
        return;
    }
    if (m_baudIndex >= m_bauds.size()) {
        finish(Error::none());
        return;
    }
    m_foundAtBaud.clear();
    const int baud = m_bauds.at(m_baudIndex);
    if (m_transport->baud() != baud && !m_transport->setBaud(baud)) {
        finish({ErrorCode::Busy, tr("The link could not switch to %1 baud (it is busy).").arg(baud)});
        return;
    }
    m_address = m_options.from;
    const bool serial = m_transport->framing() != ShuokeFraming::Plc;
    if (serial && m_transport->options().scanSkipSilent)
        probeBroadcast();
    else
        probeNextAddress();
}

void ShuokeDiscovery::probeBroadcast()
{
    auto *serial = static_cast<ShuokeSerialTransport *>(m_transport.data());
    const Frame request = Frame::make(m_transport->options().broadcast, shuoke::CmdQueryAddress);
    const Decoded<QByteArray> bytes = serial->encode(request);
    auto heard = std::make_shared<bool>(false);
    const ReplyMatcher inner = serial->matcher(request);
    SerialRequest r;
    r.bytes = *bytes.value;
    r.matcher = [inner, heard](const QByteArray &buf) {
        if (!buf.isEmpty())
            *heard = true;
        return inner(buf);
    };
    r.expectedReplyBytes = serial->wireSize(0);
    r.timeoutMs = probeTimeoutMs(serial->baud());
    r.retries = 0;
    r.note = QStringLiteral("scan: query address (broadcast)");
    LinkReply *reply = serial->link()->send(r);
    connect(reply, &LinkReply::finished, this, [this, reply, heard, serial] {
        reply->deleteLater();
        if (!reply->error().isError()) {
            const Decoded<Frame> f = serial->framing() == ShuokeFraming::Ascii
                ? shuoke::decodeAscii(reply->frame(), {m_transport->options().checksum, true})
                : shuoke::decodeRtu(reply->frame());
            if (f.ok() && shuoke::isUnicastAddress(f.value->address))
                report(f.value->address);
        }
        if (!*heard && reply->error().code == ErrorCode::Timeout) {
            ++m_skippedBauds;
            m_done += m_options.to - m_options.from + 1;
            emit progress(m_done, m_total);
            ++m_baudIndex;
            startBaud();
            return;
        }
        probeNextAddress();
    });
}

void ShuokeDiscovery::probeNextAddress()
{
    if (m_cancelled) {
        finish({ErrorCode::Cancelled, tr("The scan was cancelled.")});
        return;
    }
    while (m_address <= m_options.to && m_foundAtBaud.contains(m_address)) {
        ++m_address;
        emit progress(++m_done, m_total);
    }
    if (m_address > m_options.to) {
        ++m_baudIndex;
        startBaud();
        return;
    }
    probeAddress(m_address);
}

void ShuokeDiscovery::probeAddress(int address)
{
    const bool plc = m_transport->framing() == ShuokeFraming::Plc;
    ShuokeRequest r;
    r.frame = Frame::make(static_cast<quint8>(address), plc ? shuoke::CmdGetBaudCode : shuoke::CmdHandshake);
    r.timeoutMs = plc ? -1 : probeTimeoutMs(m_transport->baud());
    r.retries = 0;
    r.note = QStringLiteral("scan");
    m_transport->request(r, this, [this, address](const Error &e, const Frame &) {
        // A failure reply also proves that a drive listens at this address.
        if (!e || e.code == ErrorCode::DriveException)
            report(address);
        addressDone();
    });
}

void ShuokeDiscovery::addressDone()
{
    ++m_address;
    emit progress(++m_done, m_total);
    probeNextAddress();
}

} // namespace dd
