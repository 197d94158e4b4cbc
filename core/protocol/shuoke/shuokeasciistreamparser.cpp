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
    , m_buffer(std::max<qsizetype>(capacity, 2 * kMaxFrameChars))
{
}

void AsciiStreamParser::append(const QByteArray &bytes)
{
    m_buffer.append(bytes);
}

void AsciiStreamParser::clear()
{
    m_buffer.clear();
}

void AsciiStreamParser::reject(qsizetype count, const QString &why)
{
    ++m_rejected;
    m_lastError = why;
    m_buffer.discard(count);
}

std::optional<Frame> AsciiStreamParser::takeFrame()
{
    while (!m_buffer.isEmpty()) {
        const QByteArray &buffer = m_buffer.bytes();
        const qsizetype start = buffer.indexOf(kAsciiStart);
        if (start < 0) {
            m_buffer.discard(buffer.size());
            return std::nullopt;
        }
        m_buffer.discard(start);

        // buffer[0] == ':'; look for the LF, stopping at anything that breaks the frame.
        qsizetype i = 1;
        bool broken = false;
        for (; i < buffer.size(); ++i) {
            const char c = buffer.at(i);
            if (c == '\n')
                break;
            if (c == kAsciiStart) {
                reject(i, QStringLiteral("ASCII: frame interrupted by ':'"));
                broken = true;
                break;
            }
            const bool crBeforeLf = c == '\r' && (i + 1 == buffer.size() || buffer.at(i + 1) == '\n');
            if (!isHexDigit(c) && !crBeforeLf) {
                reject(i + 1,
                       QStringLiteral("ASCII: non-hex character 0x%1 in frame")
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
        if (i >= buffer.size())
            return std::nullopt; // incomplete: wait for more

        const QByteArray line = buffer.left(i + 1);
        Decoded<Frame> decoded = decodeAscii(line, m_options);
        if (decoded.ok()) {
            m_buffer.takeFront(line.size());
            return decoded.value;
        }
        ++m_rejected;
        m_buffer.discard(line.size());
        m_lastError = decoded.error;
    }
    return std::nullopt;
}

QList<Frame> AsciiStreamParser::feed(const QByteArray &bytes)
{
    // After the frames are taken the buffer holds at most one incomplete frame, so nothing
    // is lost however large `bytes` is.
    return m_buffer.appendAndTakeFrames(bytes, [this] { return takeFrame(); });
}

} // namespace dd::shuoke
