#pragma once

#include <QByteArray>
#include <QList>
#include <QtGlobal>

#include <algorithm>
#include <type_traits>

namespace dd {

// The bounded input buffer of a stream parser (Modbus RTU, Shuoke RTU and ASCII): it never
// holds more than capacity() bytes and counts every byte it discards (noise, overflow, a
// rejected frame); bytes taken as a frame are not counted.
class StreamBuffer
{
public:
    explicit StreamBuffer(qsizetype capacity);

    // Appends `bytes`; what does not fit pushes out the oldest bytes (counted as discarded).
    void append(const QByteArray &bytes);
    // Appends `bytes` in slices that fit the free space (at least one byte each) and calls
    // `drain` after each slice, and once even when `bytes` is empty: a parser that takes its
    // complete frames in `drain` loses none to the bound, however large `bytes` is.
    template <typename Drain>
    void appendInSlices(const QByteArray &bytes, Drain drain)
    {
        qsizetype at = 0;
        do {
            const qsizetype n = std::min(bytes.size() - at, std::max<qsizetype>(1, m_capacity - m_bytes.size()));
            append(bytes.mid(at, n));
            at += n;
            drain();
        } while (at < bytes.size());
    }
    // appendInSlices() that takes every complete frame after each slice: `takeFrame`
    // returns a std::optional frame, empty when no frame is complete. The frames in order.
    template <typename TakeFrame>
    auto appendAndTakeFrames(const QByteArray &bytes, TakeFrame takeFrame)
    {
        QList<typename std::invoke_result_t<TakeFrame>::value_type> frames;
        appendInSlices(bytes, [&] {
            while (auto f = takeFrame())
                frames.append(*f);
        });
        return frames;
    }
    // Drops the first `count` bytes (all there are, if fewer), counted as discarded.
    void discard(qsizetype count);
    // Removes the first `count` bytes and returns them (a frame): not counted.
    QByteArray takeFront(qsizetype count);
    // Drops everything without counting it.
    void clear() { m_bytes.clear(); }
    // Drops everything and zeroes the count.
    void reset();

    const QByteArray &bytes() const { return m_bytes; }
    qsizetype size() const { return m_bytes.size(); }
    bool isEmpty() const { return m_bytes.isEmpty(); }
    qsizetype capacity() const { return m_capacity; }
    quint64 discardedBytes() const { return m_discarded; }

private:
    qsizetype m_capacity;
    QByteArray m_bytes;
    quint64 m_discarded = 0;
};

} // namespace dd
