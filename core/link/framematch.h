#pragma once

#include <QByteArray>
#include <QString>
#include <functional>

namespace dd {

// What a reply matcher says about the bytes received so far (front of the buffer).
struct FrameMatch
{
    enum class Status {
        Incomplete, // need more bytes; nothing consumed
        Match,      // `consumed` bytes form the awaited reply (`frame`)
        Garbage,    // drop `consumed` bytes (noise, someone else's frame) and look again
        Corrupt,    // a frame-shaped run with a bad check: drop `consumed`, retry the request
        Unfit       // a valid frame from the awaited peer that does not answer the request as
                    // it must (wrong length, count, echo): drop `consumed`, retry; `reason`
                    // is the error message
    };
    Status status = Status::Incomplete;
    qsizetype consumed = 0;
    QByteArray frame;
    QString reason;

    static FrameMatch incomplete() { return {}; }
    static FrameMatch match(qsizetype n, QByteArray f) { return {Status::Match, n, std::move(f), {}}; }
    static FrameMatch garbage(qsizetype n) { return {Status::Garbage, n, {}, {}}; }
    static FrameMatch corrupt(qsizetype n) { return {Status::Corrupt, n, {}, {}}; }
    static FrameMatch unfit(qsizetype n, QString why) { return {Status::Unfit, n, {}, std::move(why)}; }
};

// Given the receive buffer, decide whether it starts with the awaited reply.
using ReplyMatcher = std::function<FrameMatch(const QByteArray &buffer)>;

} // namespace dd
