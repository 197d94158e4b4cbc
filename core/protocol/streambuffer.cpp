#include "core/protocol/streambuffer.h"

namespace dd {

StreamBuffer::StreamBuffer(qsizetype capacity)
    : m_capacity(capacity)
{
}

void StreamBuffer::append(const QByteArray &bytes)
{
    if (bytes.size() >= m_capacity) {
        m_discarded += static_cast<quint64>(m_bytes.size() + bytes.size() - m_capacity);
        m_bytes = bytes.right(m_capacity);
        return;
    }
    const qsizetype overflow = m_bytes.size() + bytes.size() - m_capacity;
    if (overflow > 0)
        discard(overflow);
    m_bytes.append(bytes);
}

void StreamBuffer::discard(qsizetype count)
{
    if (count <= 0)
        return;
    count = std::min(count, m_bytes.size());
    m_bytes.remove(0, count);
    m_discarded += static_cast<quint64>(count);
}

QByteArray StreamBuffer::takeFront(qsizetype count)
{
    const QByteArray front = m_bytes.left(count);
    m_bytes.remove(0, front.size());
    return front;
}

void StreamBuffer::reset()
{
    m_bytes.clear();
    m_discarded = 0;
}

} // namespace dd
