#include "core/protocol/modbus/modbusrtuparser.h"

#include "core/protocol/modbus/crc16.h"

#include <algorithm>

namespace dd {

namespace {

using Mode = ModbusRtuStreamParser::Mode;
using FrameCheck = ModbusRtuStreamParser::FrameCheck;
using FrameState = ModbusRtuStreamParser::FrameState;

constexpr int NeedMore = 0;
constexpr int NotAFrame = -1;

// Length of the frame that would start at p (avail bytes there), NeedMore when the bytes
// present cannot tell yet, NotAFrame when no frame can start here.
int frameLength(const quint8 *p, qsizetype avail, Mode mode, int maxFrameSize)
{
    if (avail < 2)
        return NeedMore;
    int len = NotAFrame;
    const quint8 fc = p[1];
    if (mode == Mode::Requests) {
        switch (fc) {
        case 0x03:
        case 0x06: len = 8; break;
        case 0x10: {
            if (avail < 7)
                return NeedMore;
            const int count = (p[4] << 8) | p[5];
            const int byteCount = p[6];
            if (byteCount != 2 * count)
                return NotAFrame;
            len = 9 + byteCount;
            break;
        }
        default: return NotAFrame;
        }
    } else {
        switch (fc) {
        case 0x03: {
            if (avail < 3)
                return NeedMore;
            const int byteCount = p[2];
            if (byteCount == 0 || byteCount % 2 != 0)
                return NotAFrame;
            len = 5 + byteCount;
            break;
        }
        case 0x06:
        case 0x10: len = 8; break;
        case 0x83:
        case 0x86:
        case 0x90: len = 5; break;
        default: return NotAFrame;
        }
    }
    return len > maxFrameSize ? NotAFrame : len;
}

// The first complete CRC-valid frame at any offset; otherwise Incomplete with `offset` =
// the first offset where a frame could still be completing (size when there is none).
FrameCheck scan(const QByteArray &buf, Mode mode, int maxFrameSize)
{
    const auto *p = reinterpret_cast<const quint8 *>(buf.constData());
    const qsizetype size = buf.size();
    qsizetype firstPending = -1;
    for (qsizetype k = 0; k < size; ++k) {
        const qsizetype avail = size - k;
        const int len = frameLength(p + k, avail, mode, maxFrameSize);
        if (len == NotAFrame)
            continue;
        if (len == NeedMore || len > avail) {
            if (firstPending < 0)
                firstPending = k;
            continue;
        }
        const quint16 crc = crc16Modbus(buf.constData() + k, len - 2);
        if (p[k + len - 2] == (crc & 0xFF) && p[k + len - 1] == (crc >> 8))
            return {FrameState::Complete, k, len};
    }
    return {FrameState::Incomplete, firstPending < 0 ? size : firstPending, 0};
}

bool isKnownReplyFunction(quint8 fc)
{
    switch (fc) {
    case 0x03:
    case 0x06:
    case 0x10:
    case 0x83:
    case 0x86:
    case 0x90: return true;
    default: return false;
    }
}

} // namespace

ModbusRtuStreamParser::ModbusRtuStreamParser(Mode mode, int bufferCap)
    : m_mode(mode)
    , m_bufferCap(std::max(bufferCap, MinBufferCap))
    , m_buffer(m_bufferCap)
{
}

void ModbusRtuStreamParser::feed(const QByteArray &bytes)
{
    if (bytes.isEmpty())
        return;
    // extract() leaves fewer than m_bufferCap bytes (a pending frame is shorter than the
    // cap); should that ever fail, the buffer drops the oldest bytes to keep the bound.
    m_buffer.appendInSlices(bytes, [this] { extract(); });
}

QByteArray ModbusRtuStreamParser::takeFrame()
{
    return m_frames.isEmpty() ? QByteArray() : m_frames.takeFirst();
}

qsizetype ModbusRtuStreamParser::discardPending()
{
    const qsizetype n = m_buffer.size();
    m_buffer.discard(n);
    return n;
}

void ModbusRtuStreamParser::reset()
{
    m_buffer.reset();
    m_frames.clear();
    m_droppedFrames = 0;
}

void ModbusRtuStreamParser::extract()
{
    while (!m_buffer.isEmpty()) {
        const FrameCheck c = scan(m_buffer.bytes(), m_mode, m_bufferCap);
        m_buffer.discard(c.offset);
        if (c.state != FrameState::Complete)
            return;
        if (m_frames.size() >= m_maxQueuedFrames) {
            m_frames.removeFirst();
            ++m_droppedFrames;
        }
        m_frames.append(m_buffer.takeFront(c.length));
    }
}

ModbusRtuStreamParser::FrameCheck ModbusRtuStreamParser::checkFrame(const QByteArray &bytes, Mode mode,
                                                                    int maxFrameSize)
{
    if (mode == Mode::Replies && bytes.size() >= 4 && !isKnownReplyFunction(static_cast<quint8>(bytes.at(1)))
        && hasValidCrc16(bytes))
        return {FrameState::Complete, 0, bytes.size()};
    return scan(bytes, mode, std::max(maxFrameSize, int(MinBufferCap)));
}

} // namespace dd
