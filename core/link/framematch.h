#pragma once

#include <QByteArray>
#include <functional>

namespace dd {

// What a reply matcher says about the bytes received so far (front of the buffer).
struct FrameMatch
{
    enum class Status {
        Incomplete, // need more bytes; nothing consumed
        Match,      // `consumed` bytes form the awaited reply (`frame`)
        Garbage,    // drop `consumed` bytes (noise, someone else's frame) and look again
        Corrupt     // a frame-shaped run with a bad check: drop `consumed`, retry the request
    };
    Status status = Status::Incomplete;
    qsizetype consumed = 0;
    QByteArray frame;

    static FrameMatch incomplete() { return {}; }
    static FrameMatch match(qsizetype n, QByteArray f) { return {Status::Match, n, std::move(f)}; }
    static FrameMatch garbage(qsizetype n) { return {Status::Garbage, n, {}}; }
    static FrameMatch corrupt(qsizetype n) { return {Status::Corrupt, n, {}}; }
};

// Given the receive buffer, decide whether it starts with the awaited reply.
using ReplyMatcher = std::function<FrameMatch(const QByteArray &buffer)>;

} // namespace dd
