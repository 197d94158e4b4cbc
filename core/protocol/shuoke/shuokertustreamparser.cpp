#include "core/protocol/shuoke/shuokertustreamparser.h"

#include "core/protocol/shuoke/shuokecommands.h"

#include <algorithm>

namespace dd::shuoke {

RtuStreamParser::RtuStreamParser(const RtuOptions &options, qsizetype capacity)
    : m_options(options)
    , m_buffer(std::max<qsizetype>(capacity, 2 * (kMaxDataLength + kRtuOverhead + 2)))
{
}

void RtuStreamParser::append(const QByteArray &bytes)
{
    m_buffer.append(bytes);
}

void RtuStreamParser::clear()
{
    m_buffer.clear();
}

RtuStreamParser::Scan RtuStreamParser::scanAt(qsizetype offset, bool knownLayoutsOnly,
                                              detail::RtuCandidate *found) const
{
    const qsizetype available = m_buffer.size() - offset;
    if (available < 3)
        return Scan::NeedMore;
    const char *p = m_buffer.bytes().constData() + offset;
    const quint8 commandByte = static_cast<quint8>(p[1]);
    const quint8 len = static_cast<quint8>(p[2]);
    bool pending = false;
    for (const detail::RtuCandidate &c : detail::rtuCandidates(commandByte, len, m_options)) {
        if (c.dataLength > kMaxDataLength)
            continue;
        if (knownLayoutsOnly && !isKnownLayout(commandByte, c.dataLength))
            continue;
        if (c.size > available) {
            pending = true;
            continue;
        }
        if (detail::rtuCandidateMatches(p, c, m_options)) {
            *found = c;
            return Scan::Complete;
        }
    }
    return pending ? Scan::NeedMore : Scan::Invalid;
}

std::optional<Frame> RtuStreamParser::takeFrame()
{
    detail::RtuCandidate c;
    while (!m_buffer.isEmpty()) {
        const Scan head = scanAt(0, false, &c);
        if (head == Scan::Invalid) {
            m_buffer.discard(1);
            continue;
        }
        qsizetype offset = 0;
        if (head == Scan::NeedMore) {
            // Look further on for a complete frame: the head may be a truncated frame.
            offset = -1;
            for (qsizetype k = 1; k + kRtuMinFrameSize <= m_buffer.size(); ++k) {
                if (scanAt(k, true, &c) == Scan::Complete) {
                    offset = k;
                    break;
                }
            }
            if (offset < 0)
                return std::nullopt;
            m_buffer.discard(offset);
        }
        const Frame frame = detail::rtuFrameFrom(m_buffer.bytes().constData(), c);
        m_buffer.takeFront(c.size);
        m_lastLayout = c.layout;
        return frame;
    }
    return std::nullopt;
}

QList<Frame> RtuStreamParser::feed(const QByteArray &bytes)
{
    // After the frames are taken the buffer holds at most one incomplete frame, so nothing
    // is lost however large `bytes` is.
    return m_buffer.appendAndTakeFrames(bytes, [this] { return takeFrame(); });
}

} // namespace dd::shuoke
