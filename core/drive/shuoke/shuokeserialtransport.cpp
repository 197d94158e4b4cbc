#include "core/drive/shuoke/shuokeserialtransport.h"

#include "core/link/connectionsettings.h"
#include "core/link/linkreply.h"
#include "core/link/seriallink.h"
#include "core/protocol/shuoke/shuokeasciistreamparser.h"
#include "core/protocol/shuoke/shuokecommands.h"

namespace dd {

using shuoke::Frame;

ShuokeSerialTransport::ShuokeSerialTransport(const ShuokeOptions &options, QObject *parent)
    : ShuokeTransport(options, parent)
    , m_link(new SerialLink(this))
{
    connect(m_link, &SerialLink::closed, this, &ShuokeSerialTransport::onLinkClosed);
}

ShuokeSerialTransport::~ShuokeSerialTransport() = default;

bool ShuokeSerialTransport::open(const ConnectionSettings &settings, TrafficTap *tap, Error *error)
{
    m_link->setTap(tap);
    return m_link->open(serialSettings(settings), error);
}

void ShuokeSerialTransport::close()
{
    m_link->close();
}

bool ShuokeSerialTransport::isOpen() const
{
    return m_link->isOpen();
}

QString ShuokeSerialTransport::description() const
{
    return tr("%1 @ %2 baud, Shuoke %3")
        .arg(m_link->name())
        .arg(m_link->settings().baud)
        .arg(shuokeFramingId(framing()).toUpper());
}

void ShuokeSerialTransport::cancelAll(const Error &why)
{
    m_link->cancelAll(why);
}

int ShuokeSerialTransport::baud() const
{
    return m_link->settings().baud;
}

bool ShuokeSerialTransport::setBaud(int baud)
{
    return setSerialBaud(m_link, baud);
}

shuoke::AsciiOptions ShuokeSerialTransport::asciiOptions() const
{
    shuoke::AsciiOptions o;
    o.check = options().checksum;
    return o;
}

Decoded<QByteArray> ShuokeSerialTransport::encode(const Frame &frame) const
{
    if (framing() == ShuokeFraming::Ascii)
        return shuoke::encodeAscii(frame, asciiOptions());
    return shuoke::encodeRtu(frame);
}

int ShuokeSerialTransport::wireSize(int dataBytes) const
{
    if (framing() == ShuokeFraming::Ascii)
        return 1 + 2 * (3 + dataBytes + 1) + 2;
    return shuoke::kRtuOverhead + dataBytes;
}

ReplyMatcher ShuokeSerialTransport::matcher(const Frame &request) const
{
    if (framing() == ShuokeFraming::Ascii)
        return asciiMatcher(request, asciiOptions());
    return rtuMatcher(request);
}

ReplyMatcher ShuokeSerialTransport::rtuMatcher(const Frame &request, const shuoke::RtuOptions &options)
{
    const QList<quint8> accepted = shuoke::acceptedReplyCommands(request);
    return [request, options, accepted](const QByteArray &buf) -> FrameMatch {
        if (buf.isEmpty())
            return FrameMatch::incomplete();
        const quint8 address = static_cast<quint8>(buf.at(0));
        if (!shuoke::isReplyAddress(address, request))
            return FrameMatch::garbage(1);
        if (buf.size() < 2)
            return FrameMatch::incomplete();
        const quint8 commandByte = static_cast<quint8>(buf.at(1));
        if (!accepted.contains(static_cast<quint8>(commandByte & 0x7F)))
            return FrameMatch::garbage(1);
        if (buf.size() < 3)
            return FrameMatch::incomplete();
        const quint8 len = static_cast<quint8>(buf.at(2));
        const QList<shuoke::detail::RtuCandidate> candidates = shuoke::detail::rtuCandidates(commandByte, len, options);
        bool waiting = false;
        qsizetype corruptSize = 0;
        for (const shuoke::detail::RtuCandidate &c : candidates) {
            if (c.size > buf.size()) {
                waiting = true;
                continue;
            }
            if (shuoke::detail::rtuCandidateMatches(buf.constData(), c, options)) {
                const Frame f = shuoke::detail::rtuFrameFrom(buf.constData(), c);
                if (shuoke::isReplyTo(f, request))
                    return FrameMatch::match(c.size, buf.left(c.size));
                return FrameMatch::garbage(c.size);
            }
            if (c.layout == shuoke::RtuLayout::Standard)
                corruptSize = c.size;
        }
        if (waiting)
            return FrameMatch::incomplete();
        if (corruptSize > 0)
            return FrameMatch::corrupt(corruptSize);
        return FrameMatch::garbage(1);
    };
}

ReplyMatcher ShuokeSerialTransport::asciiMatcher(const Frame &request, const shuoke::AsciiOptions &options)
{
    return [request, options](const QByteArray &buf) -> FrameMatch {
        const qsizetype start = buf.indexOf(shuoke::kAsciiStart);
        if (start < 0)
            return FrameMatch::garbage(buf.size());
        if (start > 0)
            return FrameMatch::garbage(start);
        const qsizetype lf = buf.indexOf('\n', 1);
        const qsizetype nextStart = buf.indexOf(shuoke::kAsciiStart, 1);
        if (nextStart > 0 && (lf < 0 || nextStart < lf))
            return FrameMatch::garbage(nextStart); // a frame cut short by a new one
        if (lf < 0) {
            if (buf.size() > shuoke::AsciiStreamParser::kMaxFrameChars)
                return FrameMatch::garbage(buf.size());
            return FrameMatch::incomplete();
        }
        const QByteArray line = buf.left(lf + 1);
        const Decoded<Frame> d = shuoke::decodeAscii(line, options);
        if (!d.ok())
            return FrameMatch::corrupt(line.size());
        if (shuoke::isReplyTo(*d.value, request))
            return FrameMatch::match(line.size(), line);
        return FrameMatch::garbage(line.size());
    };
}

LinkReply *ShuokeSerialTransport::start(const ShuokeRequest &request, Error *error)
{
    const Decoded<QByteArray> bytes = encode(request.frame);
    if (!bytes.ok()) {
        *error = {ErrorCode::InvalidArgument, tr("The command cannot be encoded: %1").arg(bytes.error)};
        return nullptr;
    }
    SerialRequest r;
    r.bytes = *bytes.value;
    if (request.expectReply) {
        r.matcher = matcher(request.frame);
        const shuoke::CommandInfo *info = shuoke::commandInfo(request.frame.command);
        r.expectedReplyBytes = wireSize(info ? std::max(1, info->maxReplyLength()) : 1);
    }
    r.timeoutMs = request.timeoutMs;
    r.retries = request.retries;
    r.urgent = request.urgent;
    r.peer = request.frame.address;
    r.note = request.note.isEmpty() ? shuoke::commandName(request.frame.command) : request.note;
    return m_link->send(r);
}

Decoded<Frame> ShuokeSerialTransport::decode(const LinkReply &reply, const ShuokeRequest &) const
{
    if (framing() == ShuokeFraming::Ascii)
        return shuoke::decodeAscii(reply.frame(), asciiOptions());
    return shuoke::decodeRtu(reply.frame());
}

void ShuokeSerialTransport::onLinkClosed(const Error &why)
{
    if (why.isError())
        emit linkLost(why);
}

} // namespace dd
