#include "core/drive/shuoke/shuokedrive.h"

#include "core/drive/operationjoin.h"
#include "core/protocol/shuoke/shuokevalues.h"

#include <QCoreApplication>
#include <QDateTime>

namespace dd {

using namespace shuoke;

namespace {

bool isStop(quint8 command)
{
    return command == CmdEmergencyStop || command == CmdDecelerateStop;
}

// Commands that set the axis moving.
bool startsMotion(quint8 command)
{
    switch (command) {
    case CmdMoveRelative:
    case CmdMoveRelativeDirection24:
    case CmdRunSpeed:
    case CmdRunSpeedDirection24:
    case CmdHome:
    case CmdHomeOrSCurveInt32:
    case CmdHomeOrSCurveDirection24:
    case CmdClosedLoopMove:
    case CmdClosedLoopGearedMove:
    case CmdClosedLoopMoveAbsolute: return true;
    default: return false;
    }
}

} // namespace

ShuokeDrive::ShuokeDrive(ShuokeTransport *transport, int address, QObject *parent)
    : Drive(parent)
    , m_transport(transport)
{
    m_model = transport ? transport->options().model : std::nullopt;
    DriveIdentity id;
    id.family = Family::Shuoke;
    id.address = address;
    id.model = m_model ? modelName(*m_model) : QString();
    id.link = transport ? transport->description() : QString();
    setIdentity(id);
    if (transport)
        connect(transport, &ShuokeTransport::linkLost, this, [this](const Error &why) {
            endJogLeaseLinkLost(why); // the drive has no watchdog: jogEnded() says so
            emit connectionLost(why);
        });
}

ShuokeDrive::~ShuokeDrive() = default;

void ShuokeDrive::setModel(std::optional<Model> model)
{
    m_model = model;
    mutableIdentity().model = model ? modelName(*model) : QString();
}

ByteOrder ShuokeDrive::byteOrder() const
{
    return m_transport ? m_transport->options().byteOrder : ByteOrder::LittleEndian;
}

QByteArray ShuokeDrive::int32(qint64 v) const
{
    return encodeInt32(static_cast<qint32>(v), byteOrder());
}

std::optional<qint32> ShuokeDrive::decodeInt(const QByteArray &data) const
{
    return decodeInt32(data, byteOrder());
}

bool ShuokeDrive::maySupport(quint8 command, int length) const
{
    return !m_model || isSupportedBy(command, *m_model, length);
}

Capabilities ShuokeDrive::capabilities() const
{
    Capabilities caps = Capability::ReadParameters | Capability::WriteParameters | Capability::Monitor | Capability::Jog
        | Capability::MoveRelative | Capability::MoveAbsolute | Capability::Stop | Capability::EmergencyStop
        | Capability::ReadAlarm | Capability::SetPosition;
    if (maySupport(CmdHome, 1))
        caps |= Capability::Home;
    return caps;
}

QString ShuokeDrive::unsupportedReason(Capability c) const
{
    switch (c) {
    case Capability::Enable:
        return tr("Shuoke drives have no enable command: the drive is enabled by its ENA input "
                  "(shown as \"enable input\" in the status).");
    case Capability::ClearAlarm:
        return tr("Shuoke drives keep no alarm to clear: a refused command reports its failure "
                  "code in the reply, and a limit switch clears when the axis leaves it.");
    case Capability::EeOperations:
        return tr("Shuoke drives store their settings themselves; there is no EEPROM command.");
    case Capability::Home:
        if (!maySupport(CmdHome, 1))
            return tr("The %1 has no homing command (0x3E is for the M6505 and M4505S).").arg(modelName(*m_model));
        break;
    default: break;
    }
    return Drive::unsupportedReason(c);
}

QString ShuokeDrive::commandUnavailable(quint8 command, int dataLength) const
{
    const CommandInfo *info = commandInfo(command);
    if (!info)
        return tr("0x%1 is not a Shuoke command.").arg(command, 2, 16, QLatin1Char('0'));
    const QString name = QCoreApplication::translate("dd::shuoke", info->name);
    if (!maySupport(command, dataLength))
        return tr("\"%1\" (command 0x%2) is not available on the %3.")
            .arg(name)
            .arg(command, 2, 16, QLatin1Char('0'))
            .arg(modelName(*m_model));
    if (!m_transport)
        return tr("The drive has no link.");
    const int n = dataLength >= 0 ? dataLength : std::max(0, info->maxRequestLength());
    return m_transport->cannotCarry(Frame::make(static_cast<quint8>(address()), command, QByteArray(n, '\0')));
}

Error ShuokeDrive::check(quint8 command, const QByteArray &data) const
{
    const QString unavailable = commandUnavailable(command, static_cast<int>(data.size()));
    if (!unavailable.isEmpty())
        return {ErrorCode::NotSupported, unavailable};
    const QString range = validateRequestData(command, data, byteOrder());
    if (!range.isEmpty())
        return {ErrorCode::OutOfRange, tr("Not sent to the drive at address %1: %2.").arg(address()).arg(range)};
    return Error::none();
}

Error ShuokeDrive::checkSteps(const QList<Step> &steps) const
{
    for (const Step &s : steps)
        if (const Error e = check(s.command, s.data))
            return e;
    return Error::none();
}

void ShuokeDrive::noteFailure(const Error &e)
{
    if (e.code == ErrorCode::DriveException)
        m_lastFailure = e.driveCode;
    if (e.code == ErrorCode::Timeout || e.code == ErrorCode::LinkClosed) {
        DriveStatus s = status();
        if (s.online) {
            s.online = false;
            updateStatus(s);
        }
    }
}

void ShuokeDrive::exchange(DriveReply *reply, quint8 command, const QByteArray &data, Handler done, bool expectReply,
                           bool behindQueued)
{
    if (!m_transport) {
        reply->finish({ErrorCode::LinkClosed, tr("The drive has no link.")});
        return;
    }
    ShuokeRequest r;
    r.frame = Frame::make(static_cast<quint8>(address()), command, data);
    r.expectReply = expectReply;
    r.urgent = isStop(command) && !behindQueued;
    const bool motion = startsMotion(command);
    if (motion)
        ++m_motionQueued;
    m_transport->request(r, reply, [this, done, motion](const Error &e, const Frame &f) {
        if (motion)
            --m_motionQueued;
        noteFailure(e);
        done(e, f);
    });
}

void ShuokeDrive::runSteps(DriveReply *reply, QList<Step> steps, quint64 stopsBefore)
{
    if (steps.isEmpty()) {
        reply->finish();
        return;
    }
    const Step s = steps.takeFirst();
    if (startsMotion(s.command) && m_stops != stopsBefore) {
        reply->finish({ErrorCode::Cancelled,
                       tr("A stop came before the motion command was sent: the axis was not "
                          "started.")});
        return;
    }
    exchange(reply, s.command, s.data, [this, reply, steps, stopsBefore](const Error &e, const Frame &) {
        if (e) {
            reply->finish(e);
            return;
        }
        runSteps(reply, steps, stopsBefore);
    });
}

DriveReply *ShuokeDrive::simpleCommands(const QList<Step> &steps)
{
    if (const Error e = checkSteps(steps))
        return finishedReply(e);
    DriveReply *reply = newReply();
    runSteps(reply, steps, m_stops);
    return reply;
}

// --- identity and state ------------------------------------------------------------------

DriveReply *ShuokeDrive::refreshIdentity()
{
    DriveReply *reply = newReply();
    if (m_transport)
        mutableIdentity().link = m_transport->description();
    auto afterBaud = [this, reply] {
        detectModel(reply, [this, reply] {
            reply->setInfo(QStringLiteral("model"), m_model ? modelName(*m_model) : QString());
            reply->setInfo(QStringLiteral("framing"),
                           m_transport ? shuokeFramingId(m_transport->framing()) : QString());
            DriveStatus s = status();
            s.online = true;
            updateStatus(s);
            reply->finish();
        });
    };
    auto readBaud = [this, reply, afterBaud] {
        exchange(reply, CmdGetBaudCode, {}, [reply, afterBaud](const Error &e, const Frame &f) {
            if (e && !(e.code == ErrorCode::DriveException && e.driveCode == FailureUnknownCommand)) {
                reply->finish(e);
                return;
            }
            if (!e && f.data.size() == 1) {
                const int code = static_cast<quint8>(f.data.at(0));
                reply->setInfo(QStringLiteral("baudCode"), code);
                reply->setInfo(QStringLiteral("baud"), baudRateForCode(code));
            }
            afterBaud();
        });
    };
    if (m_transport && m_transport->framing() == ShuokeFraming::Plc) {
        readBaud(); // the PLC mapping of the handshake reads 0 registers: not standard Modbus
    } else {
        exchange(reply, CmdHandshake, {}, [reply, readBaud](const Error &e, const Frame &) {
            if (e) {
                reply->finish(e);
                return;
            }
            readBaud();
        });
    }
    return reply;
}

void ShuokeDrive::detectModel(DriveReply *reply, std::function<void()> next)
{
    if (m_model) {
        next();
        return;
    }
    auto absent = [](const Error &e) {
        return (e.code == ErrorCode::DriveException && e.driveCode == FailureUnknownCommand)
            || e.code == ErrorCode::Timeout;
    };
    exchange(reply, CmdClosedLoopGetAbsolute, {}, [this, reply, next, absent](const Error &e, const Frame &) {
        if (!e) {
            setModel(Model::M6505);
            reply->setInfo(QStringLiteral("modelDetected"), true);
            next();
            return;
        }
        if (!absent(e)) {
            reply->finish(e);
            return;
        }
        exchange(reply, CmdGetHomingSpeed, {}, [this, reply, next, absent](const Error &e2, const Frame &) {
            if (e2 && !absent(e2)) {
                reply->finish(e2);
                return;
            }
            setModel(e2 ? Model::M4505 : Model::M4505S);
            reply->setInfo(QStringLiteral("modelDetected"), true);
            next();
        });
    });
}

void ShuokeDrive::applyStatusBits(DriveReply *reply, const QByteArray &statusData, std::optional<qint64> position)
{
    DriveStatus s = status();
    s.online = true;
    if (const auto st = decodeMotionStatus(statusData)) {
        s.running = st->running;
        s.enabled = st->enableInput;
        reply->setInfo(QStringLiteral("running"), st->running);
        reply->setInfo(QStringLiteral("leftLimit"), st->leftLimit);
        reply->setInfo(QStringLiteral("origin"), st->origin);
        reply->setInfo(QStringLiteral("rightLimit"), st->rightLimit);
        reply->setInfo(QStringLiteral("enableInput"), st->enableInput);
        QStringList active;
        if (st->leftLimit)
            active << QStringLiteral("left-limit");
        if (st->rightLimit)
            active << QStringLiteral("right-limit");
        if (m_lastFailure)
            active << QStringLiteral("failure-0x%1").arg(m_lastFailure, 2, 16, QLatin1Char('0'));
        reply->setInfo(QStringLiteral("conditions"), active);
    }
    if (position) {
        s.position = *position;
        s.positionValid = true;
    }
    s.alarmCode = 0; // the drive has no alarm register
    updateStatus(s);
    reply->setStatus(status());
    reply->setInfo(QStringLiteral("lastFailureCode"), m_lastFailure);
    if (m_lastFailure)
        reply->setInfo(QStringLiteral("lastFailure"), failureDescription(static_cast<quint8>(m_lastFailure)));
}

DriveReply *ShuokeDrive::readStatus()
{
    DriveReply *reply = newReply();
    exchange(reply, CmdQueryStatus, {}, [this, reply](const Error &e, const Frame &st) {
        if (e) {
            reply->setStatus(status());
            reply->finish(e);
            return;
        }
        exchange(reply, CmdQueryAbsolutePosition, {}, [this, reply, st](const Error &e2, const Frame &pos) {
            std::optional<qint64> position;
            if (!e2)
                if (const auto v = decodeInt(pos.data))
                    position = *v;
            applyStatusBits(reply, st.data, position);
            restoreMaxSpeedAtRest(reply, [reply, e2] { reply->finish(e2); });
        });
    });
    return reply;
}

DriveReply *ShuokeDrive::readAlarm()
{
    return readStatus();
}

// --- motion --------------------------------------------------------------------------

DriveReply *ShuokeDrive::doJog(qint32 speed)
{
    m_commandedDirection = speed < 0 ? -1 : (speed > 0 ? 1 : m_commandedDirection);
    return simpleCommands({{CmdRunSpeed, int32(speed)}});
}

DriveReply *ShuokeDrive::doStop(bool emergency)
{
    const quint8 command = emergency ? CmdEmergencyStop : CmdDecelerateStop;
    if (const Error e = checkSteps({{command, {}}}))
        return finishedReply(e);
    ++m_stops; // a motion sequence under way sends no further motion command
    DriveReply *reply = newReply();
    // Ahead of everything waiting on the link; and, if a motion command is waiting there
    // (it would restart the axis after the stop), once more behind it.
    const bool again = m_motionQueued > 0;
    auto join = OperationJoin::create(again ? 2 : 1, [reply](const Error &e) { reply->finish(e); });
    exchange(reply, command, {}, [join](const Error &e, const Frame &) { join->complete(e); });
    if (again)
        exchange(
            reply, command, {}, [join](const Error &e, const Frame &) { join->complete(e); }, true, true);
    return reply;
}

DriveReply *ShuokeDrive::moveRelative(qint64 distance, qint32 speed)
{
    if (!isPulseCountInRange(distance))
        return finishedReply({ErrorCode::OutOfRange,
                              tr("A relative move of %1 pulses is beyond the drive's 31-bit range.").arg(distance)});
    QList<Step> steps;
    if (speed > 0)
        steps.append(Step{CmdSetMaxSpeed, encodeUInt32(static_cast<quint32>(speed), byteOrder())});
    steps.append(Step{CmdMoveRelative, int32(distance)});
    m_commandedDirection = distance < 0 ? -1 : (distance > 0 ? 1 : m_commandedDirection);
    if (speed <= 0)
        return simpleCommands(steps);
    if (const Error e = checkSteps(steps))
        return finishedReply(e);
    DriveReply *reply = newReply();
    const quint64 stopsBefore = m_stops;
    keepMaxSpeed(reply, speed, [this, reply, steps, stopsBefore] { runSteps(reply, steps, stopsBefore); });
    return reply;
}

void ShuokeDrive::keepMaxSpeed(DriveReply *reply, qint32 speed, std::function<void()> next)
{
    // A later move before the axis came to rest: the stored value is already kept; the
    // restore waits for this move's end.
    m_restoreSeenRunning = false;
    m_restoreRestReads = 0;
    if (m_maxSpeedToRestore) {
        next();
        return;
    }
    const quint64 stopsBefore = m_stops;
    exchange(reply, CmdGetMaxSpeed, {}, [this, reply, speed, next, stopsBefore](const Error &e, const Frame &f) {
        if (m_stops != stopsBefore) { // nothing more of this move after a stop, not even its speed
            reply->finish({ErrorCode::Cancelled,
                           tr("A stop came before the motion command was sent: the axis was not started.")});
            return;
        }
        const auto stored = e ? std::nullopt : decodeInt(f.data);
        if (!stored) {
            // Not known, so it could not be put back: the move would change it for good.
            reply->finish({e ? e.code : ErrorCode::Malformed,
                           tr("The drive's stored max-speed could not be read (%1), so a move at its own speed "
                              "would overwrite it: nothing was moved. Move at speed 0 (the stored max-speed) or "
                              "try again.")
                               .arg(e ? e.message : tr("a reply of %1 bytes").arg(f.data.size()))});
            return;
        }
        if (*stored != speed)
            m_maxSpeedToRestore = quint32(*stored);
        next();
    });
}

void ShuokeDrive::restoreMaxSpeedAtRest(DriveReply *reply, std::function<void()> done)
{
    if (!m_maxSpeedToRestore) {
        done();
        return;
    }
    if (status().running) {
        m_restoreSeenRunning = true;
        m_restoreRestReads = 0;
        done();
        return;
    }
    ++m_restoreRestReads;
    // At rest after the move ran, or for three reads (a short move may be over before the
    // first), and no motion command is still on its way: the move's speed is no longer used.
    if ((!m_restoreSeenRunning && m_restoreRestReads < 3) || m_motionQueued > 0) {
        done();
        return;
    }
    const quint32 value = *m_maxSpeedToRestore;
    exchange(reply, CmdSetMaxSpeed, encodeUInt32(value, byteOrder()),
             [this, reply, value, done](const Error &e, const Frame &) {
                 if (!e && m_maxSpeedToRestore == value) {
                     m_maxSpeedToRestore.reset();
                     reply->setInfo(QStringLiteral("maxSpeedRestored"), double(value));
                 }
                 done(); // a failed restore is tried again at the next read
             });
}

DriveReply *ShuokeDrive::moveAbsolute(qint64 target, qint32 speed)
{
    m_commandedDirection = 0; // which way it goes is the drive's to know
    if (!isPulseCountInRange(target))
        return finishedReply(
            {ErrorCode::OutOfRange, tr("The target %1 is beyond the drive's 31-bit range.").arg(target)});
    QList<Step> speedStep;
    if (speed > 0)
        speedStep.append(Step{CmdSetMaxSpeed, encodeUInt32(static_cast<quint32>(speed), byteOrder())});
    const quint64 stopsBefore = m_stops;
    if (modelIs(Model::M6505)) {
        const QList<Step> steps = speedStep + QList<Step>{{CmdClosedLoopMoveAbsolute, int32(target)}};
        if (const Error e = checkSteps(steps))
            return finishedReply(e);
        DriveReply *reply = newReply();
        reply->setInfo(QStringLiteral("method"), QStringLiteral("closed-loop-absolute"));
        const auto go = [this, reply, steps, stopsBefore] { runSteps(reply, steps, stopsBefore); };
        if (speed > 0)
            keepMaxSpeed(reply, speed, go);
        else
            go();
        return reply;
    }
    // Open loop: the target relative to the pulse counter 0x37.
    if (const Error e = checkSteps(speedStep
                                   + QList<Step>{{CmdQueryAbsolutePosition, {}}, {CmdMoveRelative, int32(0)}}))
        return finishedReply(e);
    DriveReply *reply = newReply();
    reply->setInfo(QStringLiteral("method"), QStringLiteral("relative-from-position"));
    const auto go = [this, reply, target, speedStep, stopsBefore] {
        exchange(reply, CmdQueryAbsolutePosition, {},
                 [this, reply, target, speedStep, stopsBefore](const Error &e, const Frame &f) {
                     if (e) {
                         reply->finish(e);
                         return;
                     }
                     const auto pos = decodeInt(f.data);
                     if (!pos) {
                         reply->finish(
                             {ErrorCode::Malformed, tr("The drive's position reply has %1 bytes.").arg(f.data.size())});
                         return;
                     }
                     const qint64 delta = target - *pos;
                     if (!isPulseCountInRange(delta)) {
                         reply->finish(
                             {ErrorCode::OutOfRange,
                              tr("The move from %1 to %2 is beyond the drive's range.").arg(*pos).arg(target)});
                         return;
                     }
                     reply->setInfo(QStringLiteral("distance"), delta);
                     runSteps(reply, speedStep + QList<Step>{{CmdMoveRelative, int32(delta)}}, stopsBefore);
                 });
    };
    if (speed > 0)
        keepMaxSpeed(reply, speed, go);
    else
        go();
    return reply;
}

DriveReply *ShuokeDrive::home(bool positiveFirst)
{
    m_commandedDirection = 0; // which way it goes is the drive's to know
    if (!maySupport(CmdHome, 1))
        return notSupported(Capability::Home);
    return simpleCommands({{CmdHome, QByteArray(1, positiveFirst ? '\1' : '\0')}});
}

DriveReply *ShuokeDrive::setPosition(qint64 position)
{
    if (position == 0) {
        QList<Step> steps{{CmdClearAbsolutePosition, {}}};
        if (modelIs(Model::M6505))
            steps.append(Step{CmdClosedLoopSetAbsolute, {}});
        return simpleCommands(steps);
    }
    if (!modelIs(Model::M6505))
        return finishedReply({ErrorCode::InvalidArgument,
                              tr("This drive can only clear its position counter (set it to 0); "
                                 "only the M6505 sets its closed-loop position to a value.")});
    if (!isPulseCountInRange(position))
        return finishedReply({ErrorCode::OutOfRange, tr("The position %1 is beyond the drive's range.").arg(position)});
    return simpleCommands({{CmdClosedLoopSetAbsolute, int32(position)}});
}

// --- Shuoke specifics ----------------------------------------------------------------

DriveReply *ShuokeDrive::changeAddress(int newAddress)
{
    if (!isUnicastAddress(newAddress))
        return finishedReply({ErrorCode::OutOfRange, tr("A drive address is 1..247, not %1.").arg(newAddress)});
    DriveReply *r = simpleCommands({{CmdChangeAddress, QByteArray(1, static_cast<char>(newAddress))}});
    r->setInfo(QStringLiteral("effectiveAfterRestart"), true);
    return r;
}

DriveReply *ShuokeDrive::sendCommand(quint8 command, const QByteArray &data, bool validate, int address)
{
    if (validate)
        if (const Error e = check(command, data))
            return finishedReply(e);
    if (!m_transport)
        return finishedReply({ErrorCode::LinkClosed, tr("The drive has no link.")});
    const int target = address < 0 ? this->address() : address;
    if (target < 0 || target > 255)
        return finishedReply({ErrorCode::InvalidArgument, tr("%1 is not a Shuoke address.").arg(target)});
    DriveReply *reply = newReply();
    ShuokeRequest r;
    r.frame = Frame::make(static_cast<quint8>(target), command, data);
    r.expectReply = !(isBroadcastAddress(static_cast<quint8>(target)) && isStop(command));
    r.urgent = isStop(command);
    r.note = QStringLiteral("raw %1").arg(commandName(command));
    if (isStop(command))
        ++m_stops;
    const bool motion = startsMotion(command);
    if (motion)
        ++m_motionQueued;
    m_transport->request(r, reply, [this, reply, motion](const Error &e, const Frame &f) {
        if (motion)
            --m_motionQueued;
        noteFailure(e);
        if (f.address || f.command) {
            reply->setInfo(QStringLiteral("replyAddress"), f.address);
            reply->setInfo(QStringLiteral("replyCommand"), f.commandByte());
            reply->setInfo(QStringLiteral("replyData"), f.payload());
        }
        reply->finish(e);
    });
    return reply;
}

} // namespace dd
