// ServoCanDrive, part 2: parameters, live channels and motion (part 1: servocandrive.cpp).
#include "core/drive/servocan/servocandrive.h"

#include "core/drive/operationjoin.h"
#include "core/drive/servocan/servocanchannels.h"
#include "core/drive/servocan/servocanstationtracker.h"
#include "core/drive/writeverification.h"
#include "core/link/canlink.h"
#include "core/link/wiretime.h"

#include <QDateTime>
#include <algorithm>

#include <limits>
#include <memory>

namespace dd {

namespace sc = servocan;
using sc::ReadType;

namespace {

bool fitsInt32(qint64 v)
{
    return v >= std::numeric_limits<qint32>::min() && v <= std::numeric_limits<qint32>::max();
}

} // namespace

// ---- Parameters ---------------------------------------------------------------------------

DriveReply *ServoCanDrive::readParameters(const QList<int> &indices)
{
    for (int i : indices) {
        if (!sc::isValidParameterIndex(i))
            return finishedReply({ErrorCode::InvalidArgument,
                                  tr("Parameter %1 does not exist: servo-can parameters are 0 to %2.")
                                      .arg(i)
                                      .arg(sc::kMaxParameterIndex)});
    }
    DriveReply *reply = newReply();
    auto join = OperationJoin::create(
        indices.size(), [reply](const Error &e) { reply->finish(e); },
        [reply](int done, int total) { reply->reportProgress(done, total); });
    for (int i : indices) {
        const int station = m_station;
        readParameterValue(static_cast<quint8>(i), [reply, join, i, station](const Error &e, qint32 v) {
            if (e.isError()) {
                Error err = e;
                err.message = tr("Station %1, P%2: %3").arg(station).arg(i).arg(e.message);
                join->complete(err);
                return;
            }
            reply->setParameter(i, v);
            join->complete();
        });
    }
    return reply;
}

DriveReply *ServoCanDrive::writeParameters(const QList<ParameterWrite> &writes)
{
    // Validate everything before anything is sent: the protocol's limits (index 0..219,
    // int16), then the dictionary (ranges, read-only parameters).
    for (const ParameterWrite &w : writes) {
        if (!sc::isValidParameterIndex(w.index))
            return finishedReply({ErrorCode::InvalidArgument,
                                  tr("Parameter %1 does not exist: servo-can parameters are 0 to %2.")
                                      .arg(w.index)
                                      .arg(sc::kMaxParameterIndex)});
        if (w.value < std::numeric_limits<qint16>::min() || w.value > std::numeric_limits<qint16>::max())
            return finishedReply({ErrorCode::OutOfRange,
                                  tr("P%1 = %2 is out of range: servo-can parameters are 16-bit "
                                     "values from -32768 to 32767. Nothing was written.")
                                      .arg(w.index)
                                      .arg(w.value)});
    }
    if (const Error e = validateWrites(writes))
        return finishedReply(e);
    DriveReply *reply = newReply();
    auto checks = std::make_shared<QList<WriteVerification::Check>>(writes.size());
    auto join = OperationJoin::create(
        writes.size(),
        [reply, checks](const Error &e) {
            WriteVerification verification;
            for (const WriteVerification::Check &c : std::as_const(*checks))
                reply->addWriteResult(verification.add(c));
            reply->finish(e.isError() ? e : verification.summary());
        },
        [reply](int done, int total) { reply->reportProgress(done, total); });
    for (int k = 0; k < writes.size(); ++k) {
        writeOne(writes.at(k), 1, reply, [join, checks, k](const WriteVerification::Check &c) {
            (*checks)[k] = c;
            join->complete();
        });
    }
    return reply;
}

void ServoCanDrive::writeOne(const ParameterWrite &w, int attempt, DriveReply *reply,
                             const std::function<void(const WriteVerification::Check &)> &done)
{
    const int maxAttempts = 1 + std::max(0, m_link ? m_link->settings().retries : 0);
    const quint8 index = static_cast<quint8>(w.index);
    sendCommand(sc::writeParameter(m_station, index, static_cast<qint16>(w.value)),
                attempt > 1 ? QStringLiteral("write P%1 (again, %2)").arg(index).arg(attempt)
                            : QStringLiteral("write P%1").arg(index));
    // The read-back is queued behind the write, so the drive has handled the write first.
    readParameterValue(index, [this, w, attempt, maxAttempts, reply, done](const Error &e, qint32 v) {
        WriteVerification::Check c;
        c.index = w.index;
        c.requested = w.value;
        c.label = QStringLiteral("P%1").arg(w.index);
        c.acknowledged = false; // the drive acknowledges nothing: the read-back tells
        c.attempts = attempt;
        if (e.isError()) {
            c.readError = e;
            done(c);
            return;
        }
        if (v != w.value && attempt < maxAttempts) {
            writeOne(w, attempt + 1, reply, done);
            return;
        }
        c.readBack = v;
        done(c);
    });
}

// ---- Live values --------------------------------------------------------------------------

double ServoCanDrive::channelReadUs(const QStringList &channelIds) const
{
    if (!m_link)
        return 0.0;
    // One request and one reply frame (standard, 8 data bytes) per channel, all sent at
    // once: the bus carries 2n frames, and the last reply cannot come before n requests,
    // the drive's latency and one reply.
    const double frame = WireTime::canFrameUs(8, false, m_link->settings().bitrate);
    const double n = channelIds.isEmpty() ? 1.0 : double(channelIds.size());
    return std::max(2.0 * n * frame, (n + 1.0) * frame + 200.0);
}

DriveReply *ServoCanDrive::readChannels(const QStringList &channelIds)
{
    QList<servocanchannels::Channel> wanted;
    for (const QString &id : channelIds) {
        const std::optional<servocanchannels::Channel> c = servocanchannels::find(id);
        if (!c)
            return finishedReply({ErrorCode::InvalidArgument, tr("A servo-can drive has no channel \"%1\".").arg(id)});
        wanted.append(*c);
    }
    DriveReply *reply = newReply();
    reply->setSampleTimeUs(QDateTime::currentMSecsSinceEpoch() * 1000);
    auto join = OperationJoin::create(wanted.size(), [reply](const Error &e) { reply->finish(e); });
    for (int k = 0; k < wanted.size(); ++k) {
        const QString id = channelIds.at(k);
        const ReadType type = wanted.at(k).type;
        readRaw(type, 0, [this, reply, join, id, type](const Error &e, qint32 v) {
            if (e.isError()) {
                Error err = e;
                err.message = tr("Station %1, %2: %3").arg(m_station).arg(id, e.message);
                join->complete(err);
                return;
            }
            reply->setSample(id, sc::scaledValue(type, v));
            if (type == ReadType::AlarmCode)
                setAlarmCode(v);
            join->complete();
        });
    }
    return reply;
}

// ---- Motion -------------------------------------------------------------------------------

DriveReply *ServoCanDrive::setEnabled(bool on)
{
    DriveReply *reply = newReply();
    // A disable, like a stop, goes out at once (ahead of reads waiting for the link's
    // window) and again behind them, so that a queued enable or motion command cannot
    // re-enable the servo after it.
    auto join = OperationJoin::create(on ? 1 : 2, [this, reply, on](const Error &e) {
        if (!e.isError())
            setEnabledState(on);
        reply->finish(e);
    });
    const auto complete = [join](const Error &e) { join->complete(e); };
    if (!on) {
        sendCommand(sc::enable(m_station, false), QStringLiteral("disable"), complete, true);
        ++m_stopsSent;
        if (m_tracker)
            m_tracker->releaseMotion(m_station); // no motion without power: no keep-alive
    }
    sendCommand(sc::enable(m_station, on),
                on ? QStringLiteral("enable") : QStringLiteral("disable (behind queued frames)"), complete);
    return reply;
}

DriveReply *ServoCanDrive::doStop(bool emergency)
{
    const bool disables = emergency && !m_emergencyHolds;
    const QString note = disables ? QStringLiteral("stop and disable") : QStringLiteral("stop");
    // At once, ahead of anything waiting for the link's window ...
    if (!m_link || !m_link->send(stopFrame(emergency), note))
        return finishedReply(linkClosedError());
    // ... and again behind it, so that a queued motion command cannot restart the axis.
    sendCommand(stopFrame(emergency), note + QStringLiteral(" (behind queued frames)"));
    // This program no longer commands motion: its keep-alive ends, so that a drive that did
    // not hear the stop is stopped by its own watchdog (docs/reliability.md).
    ++m_stopsSent;
    if (m_tracker)
        m_tracker->releaseMotion(m_station);
    if (disables)
        setEnabledState(false);
    // Nothing acknowledges a stop; a heartbeat sent after it shows the drive heard it.
    DriveReply *reply = newReply();
    awaitHeartbeat([](quint8, qint32) { return true; }, m_stopConfirmMs,
                   [this, reply](const Error &e) {
                       if (e.code == ErrorCode::LinkClosed) {
                           reply->finish(e);
                           return;
                       }
                       if (e.isError()) {
                           reply->finish({ErrorCode::Timeout,
                                          tr("The stop command was sent, but station %1 has sent no heartbeat "
                                             "since (%2 ms): it may not have received it.")
                                              .arg(m_station)
                                              .arg(m_stopConfirmMs)});
                           return;
                       }
                       reply->finish();
                   });
    return reply;
}

DriveReply *ServoCanDrive::startMotion(const QList<CanFrameData> &frames, const QString &what,
                                       const std::function<bool(quint8, qint32)> &started)
{
    if (!m_link || !m_link->isConnected())
        return finishedReply(linkClosedError());
    // The motion lease: the keep-alive goes to this station while the motion lasts (one at
    // once, ahead of the command), and only from the program that commands it.
    if (m_tracker)
        m_tracker->holdMotion(m_station);
    const quint64 stops = m_stopsSent;
    DriveReply *reply = newReply();
    for (int i = 0; i < frames.size(); ++i) {
        const bool last = i == frames.size() - 1;
        sendCommand(frames.at(i), what, [this, reply, started, last, stops](const Error &e) {
            if (e.isError()) {
                reply->finish(e);
                return;
            }
            // The command left after frames queued before it: its lease counts from now
            // (unless a stop or a disable went out meanwhile).
            if (last && m_tracker && m_stopsSent == stops)
                m_tracker->holdMotion(m_station);
            if (last) // the motion command is on the bus: watch the heartbeats from now on
                awaitHeartbeat(started, m_motionStartMs, [reply](const Error &e2) { reply->finish(e2); });
        });
    }
    setEnabledState(true); // 0x20, 0x21 and 0x22 enable the servo
    return reply;
}

DriveReply *ServoCanDrive::doJog(qint32 speed)
{
    auto started = [speed](quint8 state, qint32) { return speed == 0 || !sc::isHeartbeatIdle(state); };
    return startMotion({sc::runSpeed(m_station, speed)}, QStringLiteral("jog %1 r/min").arg(speed), started);
}

DriveReply *ServoCanDrive::moveRelative(qint64 distance, qint32 speed)
{
    if (!fitsInt32(distance))
        return finishedReply({ErrorCode::OutOfRange,
                              tr("A relative move of %1 pulses does not fit the drive's 32-bit "
                                 "command.")
                                  .arg(distance)});
    if (speed <= 0)
        return finishedReply({ErrorCode::InvalidArgument,
                              tr("A move needs a positive positioning speed (r/min); %1 was given.").arg(speed)});
    if (distance == 0)
        return finishedReply(Error::none());
    const ServoCanStationTracker::Station st = m_tracker ? m_tracker->station(m_station)
                                                         : ServoCanStationTracker::Station{};
    const qint64 target = qint64(st.position) + distance;
    auto started = [target](quint8 state, qint32 position) {
        return !sc::isHeartbeatIdle(state) || position == target;
    };
    return startMotion(
        {sc::positioningSpeed(m_station, speed), sc::moveRelative(m_station, static_cast<qint32>(distance))},
        QStringLiteral("move by %1").arg(distance), started);
}

DriveReply *ServoCanDrive::moveAbsolute(qint64 target, qint32 speed)
{
    if (!fitsInt32(target))
        return finishedReply(
            {ErrorCode::OutOfRange, tr("Target %1 does not fit the drive's 32-bit position.").arg(target)});
    if (speed <= 0)
        return finishedReply({ErrorCode::InvalidArgument,
                              tr("A move needs a positive positioning speed (r/min); %1 was given.").arg(speed)});
    auto started = [target](quint8 state, qint32 position) {
        return !sc::isHeartbeatIdle(state) || position == target;
    };
    return startMotion(
        {sc::positioningSpeed(m_station, speed), sc::moveAbsolute(m_station, static_cast<qint32>(target))},
        QStringLiteral("move to %1").arg(target), started);
}

DriveReply *ServoCanDrive::setPosition(qint64 position)
{
    if (!fitsInt32(position))
        return finishedReply(
            {ErrorCode::OutOfRange, tr("Position %1 does not fit the drive's 32-bit position.").arg(position)});
    DriveReply *reply = newReply();
    sendCommand(sc::setPosition(m_station, static_cast<qint32>(position)),
                QStringLiteral("set position %1").arg(position));
    readRaw(ReadType::Position, 0, [this, reply, position](const Error &e, qint32 v) {
        if (e.isError()) {
            reply->finish(e);
            return;
        }
        const bool running = m_tracker && m_tracker->station(m_station).running();
        DriveStatus s = status();
        s.position = v;
        s.positionValid = true;
        updateStatus(s);
        reply->setStatus(status());
        if (!running && v != position) {
            reply->finish(
                {ErrorCode::VerifyMismatch,
                 tr("Station %1: position set to %2 but it reads back %3.").arg(m_station).arg(position).arg(v)});
            return;
        }
        reply->finish();
    });
    return reply;
}

} // namespace dd
