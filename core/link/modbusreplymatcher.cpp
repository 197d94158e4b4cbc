#include "core/link/modbusreplymatcher.h"

#include "core/common/hextext.h"
#include "core/protocol/modbus/modbusrtuparser.h"

namespace dd {

namespace {
} // namespace

ModbusReplyMatcher::ModbusReplyMatcher(const modbusrtu::Request &request, QString portName)
    : m_request(request)
    , m_port(std::move(portName))
    , m_seen(std::make_shared<Seen>())
{
}

ReplyMatcher ModbusReplyMatcher::matcher() const
{
    return [request = m_request, port = m_port, seen = m_seen](const QByteArray &buffer) {
        return match(request, port, *seen, buffer);
    };
}

FrameMatch ModbusReplyMatcher::match(const modbusrtu::Request &request, const QString &port, Seen &seen,
                                     const QByteArray &buffer)
{
    using Parser = ModbusRtuStreamParser;
    const Parser::FrameCheck c = Parser::checkFrame(buffer, Parser::Mode::Replies);
    if (c.state == Parser::FrameState::Complete) {
        if (c.offset > 0)
            return FrameMatch::garbage(c.offset); // noise before a frame
        const QByteArray frame = buffer.left(c.length);
        modbusrtu::DecodeError why = modbusrtu::DecodeError::None;
        const auto decoded = modbusrtu::decodeReply(frame, request, &why);
        if (decoded.ok())
            return FrameMatch::match(c.length, frame);
        const bool ownAddress = quint8(frame.at(0)) == request.address;
        switch (why) {
        case modbusrtu::DecodeError::AddressMismatch:
        case modbusrtu::DecodeError::FunctionMismatch:
        case modbusrtu::DecodeError::UnknownFunction:
            if (seen.foreign.size() < 8)
                seen.foreign.append(frame);
            return FrameMatch::garbage(c.length);
        default: break;
        }
        if (!ownAddress)
            return FrameMatch::garbage(c.length);
        return FrameMatch::unfit(c.length,
                                 tr("The reply from address %1 on %2 does not fit the request (%3).")
                                     .arg(request.address)
                                     .arg(port, decoded.error));
    }
    // A CRC-valid request at the front (another master asking a drive, an adapter's echo):
    // traffic of others, not a damaged reply. Before, another master's requests were taken
    // for our reply failing its CRC, and the user was sent to the cable shielding.
    const Parser::FrameCheck other = Parser::checkFrame(buffer, Parser::Mode::Requests);
    if (other.state == Parser::FrameState::Complete && other.offset == 0) {
        const QByteArray frame = buffer.left(other.length);
        if (seen.foreign.size() < 8 && frame != modbusrtu::encodeRequest(request)) // an echo is no news
            seen.foreign.append(frame);
        return FrameMatch::garbage(other.length);
    }
    // No valid frame yet. As many bytes as the reply, and the first of them cannot start a
    // frame that is still arriving (a longer one): a damaged reply.
    const int expected = std::max(modbusrtu::expectedReplySize(request), modbusrtu::ExceptionReplySize);
    if (buffer.size() >= expected && c.offset > 0)
        return FrameMatch::corrupt(buffer.size());
    return FrameMatch::incomplete();
}

QString ModbusReplyMatcher::describeCorrupt() const
{
    return tr("The reply from address %1 on %2 failed its CRC. Check the cable shielding, the bus "
              "termination and the baud rate.")
        .arg(m_request.address)
        .arg(m_port);
}

QString ModbusReplyMatcher::describeTimeout(int timeoutMs, const QByteArray &unmatched) const
{
    const int address = m_request.address;
    if (m_seen->foreign.isEmpty() && !unmatched.isEmpty())
        return tr("No complete reply from address %1 on %2 within %3 ms: only %4 byte(s) arrived, which "
                  "form no valid frame (an incomplete or garbled reply). Check the baud rate, the wiring "
                  "and the bus termination.")
            .arg(address)
            .arg(m_port)
            .arg(timeoutMs)
            .arg(unmatched.size());
    QString text = tr("No reply from address %1 on %2 within %3 ms. Check the drive address (PA51), the baud "
                      "rate, the wiring (A/B swapped?) and the bus termination.")
                       .arg(address)
                       .arg(m_port)
                       .arg(timeoutMs);
    if (m_seen->foreign.isEmpty())
        return text;
    const QByteArray stray = m_seen->foreign.constFirst();
    if (quint8(stray.at(0)) == address)
        text += QLatin1Char(' ')
            + tr("A frame with function %1 came from that address instead, which does not answer this "
                 "request (function %2).")
                  .arg(hexText(quint8(stray.at(1)), 2), hexText(m_request.function, 2));
    else
        text += QLatin1Char(' ')
            + tr("A frame from address %1 arrived instead: do two drives share an address, or does "
                 "another master talk on the bus?")
                  .arg(quint8(stray.at(0)));
    return text;
}

QList<int> ModbusReplyMatcher::peersIn(const QByteArray &bytes)
{
    using Parser = ModbusRtuStreamParser;
    QList<int> peers;
    qsizetype from = 0;
    while (from + 4 <= bytes.size()) {
        const QByteArray rest = bytes.mid(from);
        const Parser::FrameCheck c = Parser::checkFrame(rest, Parser::Mode::Replies);
        if (c.state != Parser::FrameState::Complete || c.length <= 0)
            break;
        peers.append(quint8(rest.at(c.offset)));
        from += c.offset + c.length;
    }
    return peers;
}

} // namespace dd
