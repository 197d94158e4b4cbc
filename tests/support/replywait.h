#pragma once

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QObject>
#include <QSignalSpy>
#include <QTimer>

#include <functional>

namespace dd::test {

// Runs a real event loop until `reply` (a DriveReply or LinkReply) has finished, at most
// `ms`; false if it did not. A real loop, because QTest::qWait / qWaitFor sleep 10 ms
// between event passes, which distorts the timing some tests are about.
template <typename Reply>
bool waitInEventLoop(Reply *reply, int ms)
{
    if (reply->isFinished())
        return true;
    QEventLoop loop;
    QTimer guard;
    guard.setSingleShot(true);
    QObject::connect(&guard, &QTimer::timeout, &loop, &QEventLoop::quit);
    QObject::connect(reply, &Reply::finished, &loop, &QEventLoop::quit);
    guard.start(ms);
    loop.exec();
    return reply->isFinished();
}

// Waits for `reply` to finish, at most `ms`; false if it did not (or there is no reply).
template <typename Reply>
bool waitForReply(Reply *reply, int ms)
{
    if (!reply)
        return false;
    if (reply->isFinished())
        return true; // its results are complete; finished() is only queued
    QSignalSpy spy(reply, &Reply::finished);
    return spy.wait(ms);
}

// Waits for `reply` to finish, at most `ms`; false if it did not (the operation hangs). A
// reply that has already finished gets its queued finished() delivered first.
template <typename Reply>
bool waitFinished(Reply *reply, int ms)
{
    if (reply->isFinished()) {
        QCoreApplication::processEvents(); // deliver the queued finished()
        return true;
    }
    QSignalSpy done(reply, &Reply::finished);
    return done.wait(ms);
}

// Processes events until `cond` holds, at most `ms`; returns cond() at the end.
inline bool waitUntil(const std::function<bool()> &cond, int ms)
{
    QElapsedTimer t;
    t.start();
    while (!cond() && t.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    return cond();
}

} // namespace dd::test
