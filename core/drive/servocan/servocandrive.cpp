#include "core/drive/servocan/servocandrive.h"

#include "core/drive/operationjoin.h"
#include "core/drive/servocan/servocanchannels.h"
#include "core/drive/servocan/servocanstationtracker.h"
#include "core/link/canlink.h"
#include "core/link/linkreply.h"

#include <QDateTime>
#include <QTimer>

#include <limits>
#include <memory>

namespace dd {

namespace sc = servocan;
using sc::ReadType;

namespace {

Error withContext(Error e, const QString &what)
{
    e.message = what + QStringLiteral(": ") + e.message;
    return e;
}

} // namespace

// Confirmed parameter read: answers so far, reads outstanding.
struct ServoCanDrive::ConfirmState
{
    QList<qint32> values;
    int outstanding = 0;
    int issued = 0;
    bool finished = false;
    ReadDone done;
};

ServoCanDrive::ServoCanDrive(CanLink *link, ServoCanStationTracker *tracker, int station, QObject *parent)
    : Drive(parent)
    , m_link(link)
    , m_tracker(tracker)
    , m_station(static_cast<quint8>(station))
{
    Q_ASSERT(sc::isValidStation(station));
    DriveIdentity id;
    id.family = Family::ServoCan;
    id.address = station;
    id.link = link ? link->name() : QString();
    setIdentity(id);
    if (link)
        connect(link, &CanLink::closed, this, &ServoCanDrive::onLinkClosed);
    if (tracker) {
        connect(tracker, &ServoCanStationTracker::heartbeat, this, &ServoCanDrive::onHeartbeat);
        connect(tracker, &ServoCanStationTracker::alarmReported, this, &ServoCanDrive::onAlarm);
        connect(tracker, &ServoCanStationTracker::stationOnline, this, [this](int s) { onOnline(s, true); });
        connect(tracker, &ServoCanStationTracker::stationOffline, this, [this](int s) { onOnline(s, false); });
        const ServoCanStationTracker::Station &st = tracker->station(station);
        if (st.seen) {
            DriveStatus s = status();
            s.online = st.online;
            s.running = st.running();
            s.position = st.position;
            s.positionValid = true;
            s.alarmCode = std::max(0, st.alarmCode);
            updateStatus(s);
        }
    }
}

ServoCanDrive::~ServoCanDrive() = default;

Capabilities ServoCanDrive::capabilities() const
{
    return Capability::ReadParameters | Capability::WriteParameters | Capability::Monitor | Capability::Jog
        | Capability::MoveRelative | Capability::MoveAbsolute | Capability::Enable | Capability::Stop
        | Capability::EmergencyStop | Capability::ReadAlarm | Capability::ClearAlarm | Capability::SetPosition;
}

QList<ChannelInfo> ServoCanDrive::channels() const
{
    return servocanchannels::infos();
}

QString ServoCanDrive::unsupportedReason(Capability c) const
{
    switch (c) {
    case Capability::Home:
        return tr("The servo-can protocol has no homing command. Move to the reference point "
                  "and use \"set position\" (0x50) instead.");
    case Capability::EeOperations: return tr("The servo-can protocol has no EEPROM command.");
    default: return Drive::unsupportedReason(c);
    }
}

QList<int> ServoCanDrive::allParameterIndices()
{
    QList<int> out;
    out.reserve(sc::kParameterCount);
    for (int i = 0; i < sc::kParameterCount; ++i)
        out.append(i);
    return out;
}

CanFrameData ServoCanDrive::stopFrame(bool emergency) const
{
    return emergency && !m_emergencyHolds ? sc::stopAndDisable(m_station) : sc::stop(m_station);
}

int ServoCanDrive::watchdogMs() const
{
    return int(sc::kWatchdog.count());
}

Error ServoCanDrive::linkClosedError() const
{
    return {ErrorCode::LinkClosed, tr("The CAN link to station %1 is not open.").arg(m_station)};
}

// ---- Low-level requests -------------------------------------------------------------------

void ServoCanDrive::readRaw(ReadType type, quint8 index, const ReadDone &done)
{
    if (!m_link) {
        done(linkClosedError(), 0);
        return;
    }
    const bool isParam = type == ReadType::Parameter;
    const quint8 st = m_station;
    const quint32 id = sc::frameId(st);
    const quint8 typeByte = static_cast<quint8>(type);
    CanRequest req;
    req.frame = isParam ? sc::readParameter(st, index) : sc::read(st, type);
    req.answerId = id; // the station answers with its own ID: arbitration decides when it can
    // Cheap byte test: a reply has the request's station, command, type (and index).
    req.matcher = [id, st, typeByte, index, isParam](const CanFrameData &f) {
        if (f.extended || f.id != id || f.data.size() != sc::kFrameLength)
            return false;
        const auto *b = reinterpret_cast<const quint8 *>(f.data.constData());
        return b[0] == st && b[1] == quint8(sc::Command::Read) && b[2] == typeByte && (!isParam || b[3] == index);
    };
    req.note = isParam ? QStringLiteral("read P%1").arg(index)
                       : QStringLiteral("read %1").arg(QLatin1String(sc::readTypeInfo(type).key));
    LinkReply *r = m_link->request(req);
    connect(r, &LinkReply::finished, this, [this, r, done, isParam] {
        r->deleteLater();
        if (r->error().isError()) {
            Error e = r->error();
            // Heartbeats come every 30 ms: silence for longer says more than the timeout.
            const ServoCanStationTracker::Station *st = m_tracker ? &m_tracker->station(m_station) : nullptr;
            const qint64 quietMs = st && st->seen ? m_tracker->elapsedMs() - st->lastHeartbeatMs : 0;
            if (e.code == ErrorCode::Timeout && quietMs > 100)
                e.message += QLatin1Char(' ')
                    + tr("Station %1 has sent no heartbeat for %2 ms either: has it lost "
                         "power or its CAN cable?")
                          .arg(m_station)
                          .arg(quietMs);
            done(e, 0);
            return;
        }
        const Decoded<sc::Message> d = sc::decode(r->canFrame());
        if (!d.ok()) {
            done({ErrorCode::Malformed, d.error}, 0);
            return;
        }
        done(Error::none(), isParam ? qint32(d.value->paramValue) : d.value->value);
    });
}

void ServoCanDrive::readParameterValue(quint8 index, const ReadDone &done)
{
    if (!m_confirmReads) {
        readRaw(ReadType::Parameter, index, done);
        return;
    }
    auto s = std::make_shared<ConfirmState>();
    s->done = done;
    for (int i = 0; i < 3; ++i)
        confirmRead(index, s);
}

void ServoCanDrive::confirmRead(quint8 index, const std::shared_ptr<ConfirmState> &s)
{
    constexpr int kMaxReads = 8;
    ++s->outstanding;
    ++s->issued;
    readRaw(ReadType::Parameter, index, [this, index, s](const Error &e, qint32 v) {
        --s->outstanding;
        if (s->finished)
            return;
        if (e.isError()) {
            // A read lost after its retries costs one of the reads allowed, not the parameter.
            if (e.code == ErrorCode::Timeout && s->issued < kMaxReads) {
                confirmRead(index, s);
                return;
            }
            s->finished = true;
            s->done(e, 0);
            return;
        }
        // Three equal answers: two reads damaged the same way are not rare enough (at 10 %
        // corruption about one 220-parameter backup in a hundred would hold a wrong value).
        s->values.append(v);
        if (s->values.count(v) >= 3) {
            s->finished = true;
            s->done(Error::none(), v);
            return;
        }
        if (s->outstanding > 0)
            return;
        if (s->issued < kMaxReads) {
            confirmRead(index, s);
            return;
        }
        s->finished = true;
        s->done({ErrorCode::VerifyMismatch,
                 tr("%1 reads of P%2 gave no value often enough to trust it.").arg(s->issued).arg(index)},
                0);
    });
}

void ServoCanDrive::sendCommand(const CanFrameData &frame, const QString &note, const Done &done, bool urgent)
{
    if (!m_link) {
        if (done)
            done(linkClosedError());
        return;
    }
    CanRequest req;
    req.frame = frame;
    req.note = note;
    req.urgent = urgent;
    LinkReply *r = m_link->request(req); // no matcher: in order with the reads, no reply awaited
    connect(r, &LinkReply::finished, this, [r, done] {
        r->deleteLater();
        if (done)
            done(r->error());
    });
}

void ServoCanDrive::awaitHeartbeat(const std::function<bool(quint8, qint32)> &pred, int timeoutMs, const Done &done)
{
    if (!m_tracker || !m_link) {
        done(linkClosedError());
        return;
    }
    // Only heartbeats that leave the drive after it handled the command count: the last one
    // before it may still show the previous motion. The frame was just written; a heartbeat
    // arriving within kSettleMs may have crossed it on the bus.
    constexpr qint64 kSettleMs = 2;
    auto *ctx = new QObject(this);
    auto finished = std::make_shared<bool>(false);
    auto finish = [ctx, finished, done](const Error &e) {
        if (*finished)
            return;
        *finished = true;
        ctx->deleteLater();
        done(e);
    };
    const int station = m_station;
    const qint64 notBefore = m_tracker->elapsedMs() + kSettleMs;
    ServoCanStationTracker *tracker = m_tracker;
    connect(m_tracker, &ServoCanStationTracker::heartbeat, ctx,
            [station, pred, finish, tracker, notBefore](int s, quint8 state, qint32 position) {
                if (s == station && tracker->elapsedMs() >= notBefore && pred(state, position))
                    finish(Error::none());
            });
    connect(m_link, &CanLink::closed, ctx, [this, finish] { finish(linkClosedError()); });
    QTimer::singleShot(timeoutMs, ctx, [this, finish, timeoutMs] {
        const bool online = m_tracker && m_tracker->isOnline(m_station);
        finish({ErrorCode::DriveException,
                online ? tr("Station %1 did not start within %2 ms. Is an alarm active? Is "
                            "parameter 4 = 8 (internal run control) and parameter 74 = 1 (CAN)?")
                             .arg(m_station)
                             .arg(timeoutMs)
                       : tr("No heartbeat from station %1. Is the drive powered, is parameter "
                            "74 = 1 (CAN mode) and is the station number right?")
                             .arg(m_station)});
    });
}

// ---- Identity, status, alarms -------------------------------------------------------------

DriveReply *ServoCanDrive::refreshIdentity()
{
    DriveReply *reply = newReply();
    auto values = std::make_shared<QMap<int, qint32>>();
    const QList<int> params = {sc::kParamStation, sc::kParamCommMode, sc::kParamControlMode};
    auto join = OperationJoin::create(params.size(), [this, reply, values](const Error &e) {
        if (e.isError()) {
            reply->finish(e);
            return;
        }
        QStringList warnings;
        const qint32 stationParam = values->value(sc::kParamStation);
        const qint32 comm = values->value(sc::kParamCommMode);
        const qint32 control = values->value(sc::kParamControlMode);
        if (stationParam != m_station)
            warnings << tr("Parameter 75 (station) is %1 but the drive answers as station %2.")
                            .arg(stationParam)
                            .arg(m_station);
        if (comm != 1)
            warnings << tr("Parameter 74 is %1: set it to 1 for CAN communication mode.").arg(comm);
        if (control != 8)
            warnings << tr("Parameter 4 is %1: set it to 8 (internal run control) to move the "
                           "axis over CAN.")
                            .arg(control);
        reply->setInfo(QStringLiteral("station"), stationParam);
        reply->setInfo(QStringLiteral("commMode"), comm);
        reply->setInfo(QStringLiteral("controlMode"), control);
        reply->setInfo(QStringLiteral("warnings"), warnings);
        DriveIdentity &id = mutableIdentity();
        id.link = m_link ? m_link->name() : id.link;
        id.model.clear();
        id.firmware.clear(); // the protocol has no way to read it
        reply->finish();
    });
    for (int p : params) {
        readParameterValue(static_cast<quint8>(p), [join, values, p](const Error &e, qint32 v) {
            if (!e.isError())
                values->insert(p, v);
            join->complete(e);
        });
    }
    return reply;
}

DriveReply *ServoCanDrive::readStatus()
{
    DriveReply *reply = newReply();
    auto values = std::make_shared<QMap<ReadType, qint32>>();
    const QList<ReadType> types = {ReadType::Position, ReadType::Speed, ReadType::AlarmCode};
    auto join = OperationJoin::create(types.size(), [this, reply, values](const Error &e) {
        if (e.isError()) {
            reply->setStatus(status());
            reply->finish(withContext(e, tr("Status of station %1").arg(m_station)));
            return;
        }
        DriveStatus s = status();
        const bool heartbeatFresh = m_tracker && m_tracker->isOnline(m_station);
        s.online = true;
        s.position = values->value(ReadType::Position);
        s.positionValid = true;
        s.running = heartbeatFresh ? m_tracker->station(m_station).running() : values->value(ReadType::Speed) != 0;
        // The reads can be older than the heartbeat: a move that ended meanwhile was reported
        // at rest at the position read while it still moved, short of its end. At rest by
        // the heartbeat but moving by the read: the heartbeat's position is the one at rest.
        if (heartbeatFresh && !s.running && values->value(ReadType::Speed) != 0)
            s.position = m_tracker->station(m_station).position;
        s.alarmCode = values->value(ReadType::AlarmCode);
        updateStatus(s);
        reply->setStatus(status());
        reply->setInfo(QStringLiteral("speed"), values->value(ReadType::Speed));
        reply->finish();
    });
    for (ReadType t : types) {
        readRaw(t, 0, [join, values, t](const Error &e, qint32 v) {
            if (!e.isError())
                values->insert(t, v);
            join->complete(e);
        });
    }
    return reply;
}

DriveReply *ServoCanDrive::readAlarm()
{
    DriveReply *reply = newReply();
    readRaw(ReadType::AlarmCode, 0, [this, reply](const Error &e, qint32 v) {
        if (!e.isError())
            setAlarmCode(v);
        reply->setStatus(status());
        reply->finish(e.isError() ? withContext(e, tr("Alarm of station %1").arg(m_station)) : e);
    });
    return reply;
}

DriveReply *ServoCanDrive::clearAlarm()
{
    DriveReply *reply = newReply();
    const qint64 deadline = QDateTime::currentMSecsSinceEpoch() + m_alarmClearMs;
    sendCommand(sc::clearAlarm(m_station), QStringLiteral("clear alarm"), [this, reply, deadline](const Error &e) {
        if (e.isError()) {
            reply->finish(e);
            return;
        }
        pollAlarmCleared(reply, deadline);
    });
    return reply;
}

void ServoCanDrive::pollAlarmCleared(DriveReply *reply, qint64 deadlineMs)
{
    readRaw(ReadType::AlarmCode, 0, [this, reply, deadlineMs](const Error &e, qint32 code) {
        if (e.isError()) {
            reply->finish(withContext(e, tr("Alarm of station %1").arg(m_station)));
            return;
        }
        setAlarmCode(code);
        if (code == 0) {
            reply->setStatus(status());
            reply->finish();
            return;
        }
        if (QDateTime::currentMSecsSinceEpoch() < deadlineMs) {
            QTimer::singleShot(30, reply, [this, reply, deadlineMs] { pollAlarmCleared(reply, deadlineMs); });
            return;
        }
        Error err{ErrorCode::DriveException,
                  tr("Station %1 still reports alarm %2 after the clear command. Remove the "
                     "cause of the alarm first.")
                      .arg(m_station)
                      .arg(code)};
        err.driveCode = code;
        reply->setStatus(status());
        reply->finish(err);
    });
}

void ServoCanDrive::setAlarmCode(int code)
{
    DriveStatus s = status();
    s.alarmCode = code;
    updateStatus(s);
}

void ServoCanDrive::setEnabledState(bool on)
{
    DriveStatus s = status();
    s.enabled = on;
    updateStatus(s);
}

void ServoCanDrive::onHeartbeat(int station, quint8 state, qint32 position)
{
    if (station != m_station)
        return;
    DriveStatus s = status();
    s.online = true;
    s.running = !sc::isHeartbeatIdle(state);
    s.position = position;
    s.positionValid = true;
    updateStatus(s);
}

void ServoCanDrive::onAlarm(int station, int code)
{
    if (station == m_station)
        setAlarmCode(code);
}

void ServoCanDrive::onOnline(int station, bool online)
{
    if (station != m_station)
        return;
    DriveStatus s = status();
    s.online = online;
    updateStatus(s);
    if (!online && isJogging() && m_link && m_link->isConnected()) {
        // It may have lost only its voice: stop it in case it still hears; the stop is not
        // confirmed, so jogEnded() names the drive's watchdog.
        DriveReply *r = stop(false);
        connect(r, &DriveReply::finished, r, &QObject::deleteLater);
    }
}

void ServoCanDrive::onLinkClosed(const Error &why)
{
    endJogLeaseLinkLost(why);
    DriveStatus s = status();
    s.online = false;
    updateStatus(s);
    if (why.isError())
        emit connectionLost(why);
}

} // namespace dd
