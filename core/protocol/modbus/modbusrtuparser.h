#pragma once

#include "core/protocol/streambuffer.h"

#include <QByteArray>
#include <QList>
#include <QtGlobal>

namespace dd {

// Incremental Modbus RTU framer for byte streams (serial port, pty) without timing
// information: feed() whatever arrived, then takeFrame() until it returns empty.
//
// Mode::Requests (drive side) knows the request layouts: 0x03 / 0x06 are 8 bytes, 0x10 is
// 9 + N (N = byte count, which must equal 2 x register count).
// Mode::Replies (host side) knows the reply layouts without knowing the request: 0x03 is
// 5 + N (N even, non-zero), 0x06 / 0x10 are 8, an exception (0x83 / 0x86 / 0x90) is 5.
//
// A frame is delivered only when its CRC checks; the address byte is not judged.
// Resynchronisation: a byte that cannot start a frame (unknown function code, impossible
// byte count, claimed length above bufferCap) or whose frame fails the CRC is
// discarded, one byte at a time. Look-ahead: while the bytes at the front still wait for
// their (claimed) length, a complete CRC-valid frame further on is delivered at once and
// the bytes before it are discarded; this frees a real frame stuck behind noise that
// happened to look like the header of a long frame. (The price: a frame embedded in the
// data of a longer frame still arriving would be taken for a frame, a 1 in 65536 CRC
// coincidence at an offset that also carries a valid function code.)
//
// Bounds: bufferCap is both the longest frame accepted and the bound of the bytes held
// while waiting for a frame: a header claiming a longer frame is noise, so fewer than
// bufferCap bytes ever wait (feed() appends long input in slices and frames it as it
// goes). The default, 256, is the Modbus RTU limit; a host that reads at most 20
// registers may set 45 to resynchronise sooner. Delivered frames wait in a queue of at
// most DefaultMaxQueuedFrames (the oldest is dropped and counted). Every byte discarded
// is counted.
class ModbusRtuStreamParser
{
public:
    enum class Mode { Requests, Replies };

    enum class FrameState {
        Incomplete, // no complete frame yet; more bytes may complete one
        Complete    // a CRC-valid frame at [offset, offset + length)
    };
    struct FrameCheck
    {
        FrameState state = FrameState::Incomplete;
        qsizetype offset = 0; // Complete: bytes before the frame (noise, local echo)
                              // Incomplete: bytes at the front that cannot start a frame
        qsizetype length = 0; // Complete: frame length; bytes after it are not part of it
    };

    static constexpr int DefaultBufferCap = 256; // Modbus RTU ADU limit
    static constexpr int MinBufferCap = 8;       // the 8-byte frames must fit
    static constexpr int DefaultMaxQueuedFrames = 64;

    // bufferCap below MinBufferCap is raised to it.
    explicit ModbusRtuStreamParser(Mode mode, int bufferCap = DefaultBufferCap);

    void feed(const QByteArray &bytes);
    bool hasFrame() const { return !m_frames.isEmpty(); }
    QByteArray takeFrame(); // the oldest complete frame (CRC included), or empty

    // Discards the bytes still waiting (call it on inter-frame silence or after a timeout)
    // and returns how many there were; they are counted as discarded.
    qsizetype discardPending();
    void reset(); // empties buffer and queue, zeroes the counters

    Mode mode() const { return m_mode; }
    int bufferCap() const { return m_bufferCap; }
    qsizetype pendingBytes() const { return m_buffer.size(); }
    quint64 discardedBytes() const { return m_buffer.discardedBytes(); }
    quint64 droppedFrames() const { return m_droppedFrames; }

    // Tolerant "is a frame complete?" for a serial link's reply matcher, over everything
    // received since the request was sent. It finds the first CRC-valid frame at any
    // offset (skipping noise and an adapter's local echo of the request), reports trailing
    // bytes by returning the frame's length, and - Mode::Replies and offset 0 only -
    // accepts a CRC-valid buffer of >= 4 bytes whose function code it does not know (e.g.
    // 0x04 or 0x84), so the link can report it instead of waiting for a timeout.
    static FrameCheck checkFrame(const QByteArray &bytes, Mode mode, int maxFrameSize = DefaultBufferCap);

private:
    void extract();

    Mode m_mode;
    int m_bufferCap;
    int m_maxQueuedFrames = DefaultMaxQueuedFrames;
    StreamBuffer m_buffer;
    QList<QByteArray> m_frames;
    quint64 m_droppedFrames = 0;
};

} // namespace dd
