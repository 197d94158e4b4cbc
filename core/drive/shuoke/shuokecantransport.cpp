#include "core/drive/shuoke/shuokecantransport.h"
#include "core/protocol/familytraits.h"

#include "core/link/connectionsettings.h"
#include "core/link/linkreply.h"
#include "core/protocol/shuoke/shuokecan.h"
#include "core/protocol/shuoke/shuokecommands.h"

namespace dd {

using shuoke::Frame;

ShuokeCanTransport::ShuokeCanTransport(const ShuokeOptions &options, QObject *parent)
    : ShuokeTransport(options, parent)
    , m_link(new CanLink(this))
{
    connect(m_link, &CanLink::closed, this, &ShuokeCanTransport::onLinkClosed);
}

ShuokeCanTransport::~ShuokeCanTransport() = default;

bool ShuokeCanTransport::open(const ConnectionSettings &settings, TrafficTap *tap, Error *error)
{
    CanSettings can;
    if (!CanSettings::parse(settings.can, &can)) {
        if (error)
            *error = {ErrorCode::InvalidArgument,
                      tr("\"%1\" is not a CAN interface: write plugin:interface, e.g. socketcan:can0 "
                         "or virtualcan:can0.")
                          .arg(settings.can)};
        return false;
    }
    can.bitrate = settings.bitrate > 0 ? settings.bitrate : familyTraits(Family::Shuoke).defaultBitrate;
    can.responseTimeoutMs = settings.timeoutMs >= 0 ? settings.timeoutMs : kDefaultResponseMs;
    if (settings.retries >= 0)
        can.retries = settings.retries;
    m_bitrate = can.bitrate;
    m_link->setTap(tap);
    return m_link->open(can, error);
}

void ShuokeCanTransport::close()
{
    m_link->close();
}

bool ShuokeCanTransport::isOpen() const
{
    return m_link->isConnected();
}

QString ShuokeCanTransport::description() const
{
    return tr("%1, %2 kbit/s, Shuoke CAN").arg(m_link->name()).arg(m_bitrate / 1000);
}

void ShuokeCanTransport::cancelAll(const Error &why)
{
    m_link->cancelAll(why);
}

QString ShuokeCanTransport::cannotCarry(const Frame &frame) const
{
    const QString base = ShuokeTransport::cannotCarry(frame);
    if (!base.isEmpty())
        return base;
    if (frame.data.size() > shuoke::kCanMaxData)
        return tr("A command with %1 data bytes does not fit a CAN frame (at most %2).")
            .arg(frame.data.size())
            .arg(shuoke::kCanMaxData);
    return QString();
}

CanMatcher ShuokeCanTransport::matcher(const Frame &request)
{
    return [request](const CanFrameData &can) {
        const Decoded<Frame> f = shuoke::decodeCan(can);
        return f.ok() && shuoke::isReplyTo(*f.value, request);
    };
}

LinkReply *ShuokeCanTransport::start(const ShuokeRequest &request, Error *error)
{
    const Decoded<CanFrameData> can = shuoke::encodeCan(request.frame, options().can);
    if (!can.ok()) {
        *error = {ErrorCode::InvalidArgument, tr("The command cannot be encoded: %1").arg(can.error)};
        return nullptr;
    }
    CanRequest r;
    r.frame = *can.value;
    if (request.expectReply)
        r.matcher = matcher(request.frame);
    r.timeoutMs = request.timeoutMs;
    r.retries = request.retries;
    r.urgent = request.urgent;
    r.note = request.note.isEmpty() ? shuoke::commandName(request.frame.command) : request.note;
    return m_link->request(r);
}

Decoded<Frame> ShuokeCanTransport::decode(const LinkReply &reply, const ShuokeRequest &) const
{
    return shuoke::decodeCan(reply.canFrame());
}

void ShuokeCanTransport::onLinkClosed(const Error &why)
{
    if (why.isError())
        emit linkLost(why);
}

} // namespace dd
