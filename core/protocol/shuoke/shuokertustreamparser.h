#pragma once

#include "core/protocol/shuoke/shuokeframe.h"
#include "core/protocol/shuoke/shuokertu.h"
#include "core/protocol/streambuffer.h"

#include <QByteArray>
#include <QList>

#include <optional>

namespace dd::shuoke {

// Cuts Shuoke RTU frames out of a byte stream (serial port reads of any size).
//
// - Resynchronises after garbage: a position that cannot start a valid frame is dropped
//   one byte at a time. While the frame at the head is still incomplete, a complete
//   valid frame further on (with a command/length pair the table knows) wins, and the
//   bytes before it are dropped, so a truncated frame never blocks the next one.
// - Never reads past its buffer; the buffer is bounded (`capacity`): the oldest bytes
//   are dropped when more arrive than it holds.
// - An incomplete frame stays buffered until more bytes arrive or clear() is called (the
//   link calls it when a request times out).
class RtuStreamParser
{
public:
    static constexpr qsizetype kDefaultCapacity = 256;
    static constexpr int kMaxDataLength = 16; // longer len bytes are treated as garbage

    explicit RtuStreamParser(const RtuOptions &options = {}, qsizetype capacity = kDefaultCapacity);

    // Buffers `bytes`; beyond `capacity` the oldest buffered bytes are dropped (call
    // takeFrame() in between, or use feed(), which never loses a frame that way).
    void append(const QByteArray &bytes);
    // The next complete frame, discarding garbage before it; nullopt when none is complete.
    std::optional<Frame> takeFrame();
    // Every complete frame in the buffer plus `bytes`, whatever the size of `bytes`.
    QList<Frame> feed(const QByteArray &bytes);
    void clear();

    qsizetype bufferedSize() const { return m_buffer.size(); }
    qsizetype capacity() const { return m_buffer.capacity(); }
    quint64 discardedBytes() const { return m_buffer.discardedBytes(); }
    // Layout of the last frame taken (shows a drive that counts the CRC in len).
    RtuLayout lastLayout() const { return m_lastLayout; }
    const RtuOptions &options() const { return m_options; }
    void setOptions(const RtuOptions &options) { m_options = options; }

private:
    enum class Scan { Complete, NeedMore, Invalid };
    Scan scanAt(qsizetype offset, bool knownLayoutsOnly, detail::RtuCandidate *found) const;

    RtuOptions m_options;
    StreamBuffer m_buffer;
    RtuLayout m_lastLayout = RtuLayout::Standard;
};

} // namespace dd::shuoke
