#pragma once

#include "core/protocol/shuoke/shuokeascii.h"
#include "core/protocol/shuoke/shuokeframe.h"
#include "core/protocol/streambuffer.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <optional>

namespace dd::shuoke {

// Cuts Shuoke ASCII frames (":" ... CR LF) out of a character stream.
//
// - Anything before a ':' is dropped. A ':' inside a frame starts a new frame (the
//   partial one is rejected). A character that is neither a hex digit nor the CR before
//   LF rejects the frame; the parser then waits for the next ':'.
// - A frame longer than kMaxFrameChars without its LF is rejected.
// - Frames whose check byte or length do not match are rejected (see lastError()).
// - The buffer never exceeds `capacity` bytes; it never reads past it.
class AsciiStreamParser
{
public:
    static constexpr qsizetype kDefaultCapacity = 512;
    // ':' + hex of addr, cmd, len, up to 16 data bytes, check + CR LF
    static constexpr qsizetype kMaxFrameChars = 1 + 2 * (3 + 16 + 1) + 2;

    explicit AsciiStreamParser(const AsciiOptions &options = {}, qsizetype capacity = kDefaultCapacity);

    // Buffers `bytes`; beyond `capacity` the oldest buffered bytes are dropped (call
    // takeFrame() in between, or use feed(), which never loses a frame that way).
    void append(const QByteArray &bytes);
    // The next complete, valid frame, dropping garbage and rejected frames before it.
    std::optional<Frame> takeFrame();
    // Every complete frame in the buffer plus `bytes`, whatever the size of `bytes`.
    QList<Frame> feed(const QByteArray &bytes);
    void clear();

    qsizetype bufferedSize() const { return m_buffer.size(); }
    qsizetype capacity() const { return m_buffer.capacity(); }
    quint64 discardedBytes() const
    {
        return m_buffer.discardedBytes();
    } // bytes outside any frame, or of rejected frames
    quint64 rejectedFrames() const { return m_rejected; }
    QString lastError() const { return m_lastError; }
    const AsciiOptions &options() const { return m_options; }
    void setOptions(const AsciiOptions &options) { m_options = options; }

private:
    void reject(qsizetype count, const QString &why);

    AsciiOptions m_options;
    StreamBuffer m_buffer;
    quint64 m_rejected = 0;
    QString m_lastError;
};

} // namespace dd::shuoke
