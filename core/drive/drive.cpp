#include "core/drive/drive.h"

#include "core/params/parameterdictionary.h"

#include <QDateTime>
#include <QSet>

namespace dd {

Drive::Drive(QObject *parent)
    : QObject(parent)
    , m_jogLease(this)
{
    qRegisterMetaType<dd::DriveStatus>();
    qRegisterMetaType<dd::JogEnd>();
    m_jogLease.setSingleShot(true);
    m_jogLease.setTimerType(Qt::PreciseTimer);
    connect(&m_jogLease, &QTimer::timeout, this, &Drive::onJogLeaseTimeout);
}

Drive::~Drive() = default;

void Drive::setDictionary(std::shared_ptr<const ParameterDictionary> dictionary)
{
    m_dictionary = std::move(dictionary);
}

const ParameterDictionary &Drive::parameterDictionary() const
{
    if (m_dictionary)
        return *m_dictionary;
    return ParameterDictionary::bundled(family());
}

Error Drive::validateWrite(const ParameterWrite &write) const
{
    return parameterDictionary().validateWrite(write.index, write.value);
}

Error Drive::validateWrites(const QList<ParameterWrite> &writes) const
{
    if (writes.isEmpty())
        return {ErrorCode::InvalidArgument, tr("No parameter to write.")};
    QSet<int> seen;
    for (const ParameterWrite &w : writes) {
        const Error e = validateWrite(w);
        if (e.isError())
            return e;
        if (seen.contains(w.index))
            return {ErrorCode::InvalidArgument,
                    tr("%1 is given twice. Nothing was written.").arg(parameterDictionary().label(w.index))};
        seen.insert(w.index);
    }
    return Error::none();
}

QString Drive::unsupportedReason(Capability c) const
{
    if (capabilities().testFlag(c))
        return {};
    return tr("The %1 drive family has no \"%2\" operation.").arg(familyId(family()), capabilityId(c));
}

DriveReply *Drive::newReply()
{
    return new DriveReply(this);
}

DriveReply *Drive::finishedReply(const Error &error)
{
    DriveReply *r = newReply();
    r->finish(error);
    return r;
}

DriveReply *Drive::notSupported(Capability c)
{
    return finishedReply({ErrorCode::NotSupported, unsupportedReason(c)});
}

DriveReply *Drive::refreshIdentity()
{
    return finishedReply(Error::none());
}

DriveReply *Drive::readStatus()
{
    DriveReply *r = newReply();
    r->setStatus(m_status);
    r->finish();
    return r;
}

DriveReply *Drive::readParameters(const QList<int> &)
{
    return notSupported(Capability::ReadParameters);
}
DriveReply *Drive::writeParameters(const QList<ParameterWrite> &)
{
    return notSupported(Capability::WriteParameters);
}
DriveReply *Drive::readChannels(const QStringList &)
{
    return notSupported(Capability::Monitor);
}
DriveReply *Drive::readAlarm()
{
    return notSupported(Capability::ReadAlarm);
}
DriveReply *Drive::clearAlarm()
{
    return notSupported(Capability::ClearAlarm);
}
DriveReply *Drive::setEnabled(bool)
{
    return notSupported(Capability::Enable);
}
DriveReply *Drive::moveRelative(qint64, qint32)
{
    return notSupported(Capability::MoveRelative);
}
DriveReply *Drive::moveAbsolute(qint64, qint32)
{
    return notSupported(Capability::MoveAbsolute);
}
DriveReply *Drive::home(bool)
{
    return notSupported(Capability::Home);
}
DriveReply *Drive::setPosition(qint64)
{
    return notSupported(Capability::SetPosition);
}
DriveReply *Drive::eeOperation(EeOperation)
{
    return notSupported(Capability::EeOperations);
}
DriveReply *Drive::doJog(qint32)
{
    return notSupported(Capability::Jog);
}
DriveReply *Drive::doStop(bool)
{
    return notSupported(Capability::Stop);
}

DriveReply *Drive::jog(qint32 speed)
{
    if (!hasCapability(Capability::Jog))
        return notSupported(Capability::Jog);
    DriveReply *r = doJog(speed);
    m_jogging = true;
    m_jogLease.start(m_jogLeaseMs);
    return r;
}

DriveReply *Drive::stop(bool emergency)
{
    emit stopRequested(emergency);
    const bool wasJogging = m_jogging;
    const bool leaseExpired = m_leaseStopping;
    endJogLease();
    // the strongest stop this family has
    DriveReply *inner = doStop(emergency && hasCapability(Capability::EmergencyStop));
    // The caller's reply says what stops the axis; it finishes right after the family's.
    DriveReply *reply = newReply();
    connect(inner, &DriveReply::finished, reply, [this, inner, reply, wasJogging, leaseExpired] {
        inner->deleteLater();
        const JogEnd end = describeStop(inner->error(), leaseExpired);
        reply->setStatus(inner->status());
        for (auto it = inner->info().cbegin(); it != inner->info().cend(); ++it)
            reply->setInfo(it.key(), it.value());
        reply->setInfo(QStringLiteral("stoppedBy"), stoppedById(end.stoppedBy));
        reply->finish(inner->error());
        if (wasJogging)
            emit jogEnded(end);
    });
    return reply;
}

JogEnd Drive::describeStop(const Error &stopError, bool leaseExpired) const
{
    JogEnd end;
    end.leaseExpired = leaseExpired;
    const QString lead = leaseExpired
        ? tr("The jog lease was not renewed within %1 ms.").arg(m_jogLeaseMs) + QLatin1Char(' ')
        : QString();
    if (!stopError.isError()) {
        end.stoppedBy = JogEnd::StoppedBy::Command;
        end.message = lead + tr("The axis was stopped by a stop command.");
    } else if (watchdogMs() > 0) {
        end.stoppedBy = JogEnd::StoppedBy::DriveWatchdog;
        end.message = lead
            + tr("%1 The drive's own watchdog stops the axis %2 ms after it last heard from "
                 "DriveDesk.")
                  .arg(stopError.message)
                  .arg(watchdogMs());
    } else {
        end.stoppedBy = JogEnd::StoppedBy::Nothing;
        end.message = lead
            + tr("%1 This drive has no watchdog: the axis may still be moving. Use the "
                 "machine's emergency stop.")
                  .arg(stopError.message);
    }
    return end;
}

void Drive::renewJogLease()
{
    if (m_jogging)
        m_jogLease.start(m_jogLeaseMs);
}

void Drive::endJogLease()
{
    m_jogging = false;
    m_jogLease.stop();
}

void Drive::endJogLeaseLinkLost(const Error &why)
{
    if (!m_jogging)
        return;
    endJogLease();
    Error e = why;
    if (e.message.isEmpty())
        e.message = tr("The link to the drive was closed.");
    if (!e.isError())
        e.code = ErrorCode::LinkClosed;
    JogEnd end = describeStop(e, false);
    end.linkLost = true;
    emit jogEnded(end);
}

void Drive::onJogLeaseTimeout()
{
    if (!m_jogging)
        return;
    m_leaseStopping = true;
    DriveReply *r = stop(false);
    m_leaseStopping = false;
    connect(r, &DriveReply::finished, r, &QObject::deleteLater);
    emit jogLeaseExpired();
}

void Drive::updateStatus(const DriveStatus &s)
{
    const DriveStatus old = m_status;
    m_status = s;
    m_status.updatedMs = QDateTime::currentMSecsSinceEpoch();
    if (old.alarmCode != s.alarmCode)
        emit alarmChanged(s.alarmCode);
    if (old.online != s.online || old.running != s.running || old.enabled != s.enabled || old.position != s.position
        || old.positionValid != s.positionValid || old.alarmCode != s.alarmCode)
        emit statusChanged(m_status);
}

} // namespace dd
