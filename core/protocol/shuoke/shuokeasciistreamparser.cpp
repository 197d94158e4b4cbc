#include "core/protocol/shuoke/shuokeasciistreamparser.h"

#include <algorithm>

namespace dd::shuoke {

namespace {
bool isHexDigit(char c)
{
    return (c >= '0' && c <= '9') || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f');
}
} // namespace

AsciiStreamParser::AsciiStreamParser(const AsciiOptions &options, qsizetype capacity)
    : m_options(options)
    , m_capacity(std::max<qsizetype>(capacity, 2 * kMaxFrameChars))
{
}

void AsciiStreamParser::append(const QByteArray &bytes)
{
    if (bytes.size() >= m_capacity) {
        m_discarded += static_cast<quint64>(m_buffer.size() + bytes.size() - m_capacity);
        m_buffer = bytes.right(m_capacity);
        return;
    }
    const qsizetype overflow = m_buffer.size() + bytes.size() - m_capacity;
    if (overflow > 0)
        discard(overflow);
    m_buffer.append(bytes);
}

void AsciiStreamParser::clear()
{
    m_buffer.clear();
}

void AsciiStreamParser::discard(qsizetype count)
{
    count = std::min(count, m_buffer.size());
    m_buffer.remove(0, count);
    m_discarded += static_cast<quint64>(count);
}

void AsciiStreamParser::reject(qsizetype count, const QString &why)
{
    ++m_rejected;
    m_lastError = why;
    discard(count);
}

std::optional<Frame> AsciiStreamParser::takeFrame()
{
    while (!m_buffer.isEmpty()) {
        const qsizetype start = m_buffer.indexOf(kAsciiStart);
        if (start < 0) {
            discard(m_buffer.size());
            return std::nullopt;
        }
        discard(start);

        // m_buffer[0] == ':'; look for the LF, stopping at anything that breaks the frame.
        qsizetype i = 1;
        bool broken = false;
        for (; i < m_buffer.size(); ++i) {
            const char c = m_buffer.at(i);
            if (c == '\n')
                break;
            if (c == kAsciiStart) {
                reject(i, QStringLiteral("ASCII: frame interrupted by ':'"));
                broken = true;
                break;
            }
            const bool crBeforeLf = c == '\r' && (i + 1 == m_buffer.size() || m_buffer.at(i + 1) == '\n');
            if (!isHexDigit(c) && !crBeforeLf) {
                reject(i + 1, QStringLiteral("ASCII: non-hex character 0x%1 in frame")
                                  .arg(static_cast<quint8>(c), 2, 16, QLatin1Char('0')));
                broken = true;
                break;
            }
            if (i + 1 >= kMaxFrameChars) {
                reject(i + 1, QStringLiteral("ASCII: frame longer than %1 characters").arg(kMaxFrameChars));
                broken = true;
                break;
            }
        }
        if (broken)
            continue;
        if (i >= m_buffer.size())
            return std::nullopt; // incomplete: wait for more

        const QByteArray line = m_buffer.left(i + 1);
        m_buffer.remove(0, i + 1);
        Decoded<Frame> decoded = decodeAscii(line, m_options);
        if (decoded.ok())
            return decoded.value;
        ++m_rejected;
        m_discarded += static_cast<quint64>(line.size());
        m_lastError = decoded.error;
    }
    return std::nullopt;
}

QList<Frame> AsciiStreamParser::feed(const QByteArray &bytes)
{
    // In pieces that fit the free space: after the frames are taken, the buffer holds at
    // most one incomplete frame, so nothing is lost however large `bytes` is.
    QList<Frame> out;
    qsizetype at = 0;
    do {
        const qsizetype n = std::min(bytes.size() - at, std::max<qsizetype>(1, m_capacity - m_buffer.size()));
        append(bytes.mid(at, n));
        at += n;
        while (std::optional<Frame> f = takeFrame())
            out.append(*f);
    } while (at < bytes.size());
    return out;
}

} // namespace dd::shuoke

