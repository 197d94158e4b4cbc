#pragma once

#include "core/common/error.h"
#include "core/drive/drivereply.h"
#include "core/drive/drivetypes.h"

#include <QObject>
#include <QTimer>
#include <memory>

namespace dd {

class ParameterDictionary;

// One drive on a link: the API the CLI, the GUI and the tests use, the same for every
// family. Every operation returns a DriveReply (see there); operations a family lacks
// finish with ErrorCode::NotSupported and a reason. Values are validated against the
// parameter dictionary before anything is sent; every parameter write is read back.
//
// Jog is a lease: jog() starts motion and a lease of jogLeaseMs() (300 ms by default);
// whoever holds it calls renewJogLease() at least every 100 ms. If the lease runs out the
// drive is stopped from this (I/O) side and jogLeaseExpired() is emitted. Any stop()
// ends the lease. However a jog ends, jogEnded() says what stops the axis: a stop command
// the drive received, or — when the stop could not be sent or confirmed (link gone, drive
// silent) — the drive's own watchdog (watchdogMs() > 0), or nothing (the user must use
// the machine's emergency stop). Every stop reply carries the same as info "stoppedBy"
// ("command", "drive-watchdog", "nothing"). A Drive lives in the thread of its link.
class Drive : public QObject
{
    Q_OBJECT
public:
    explicit Drive(QObject *parent = nullptr);
    ~Drive() override;

    virtual Family family() const = 0;
    virtual Capabilities capabilities() const = 0;
    virtual QList<ChannelInfo> channels() const = 0;
    // Why an action is unavailable on this drive (empty when it is available).
    virtual QString unsupportedReason(Capability c) const;

    DriveIdentity identity() const { return m_identity; }
    int address() const { return m_identity.address; }
    DriveStatus status() const { return m_status; }
    bool hasCapability(Capability c) const { return capabilities().testFlag(c); }

    // The dictionary values are validated against: the one set here (a user's file), else
    // the family's bundled dictionary.
    std::shared_ptr<const ParameterDictionary> dictionary() const { return m_dictionary; }
    void setDictionary(std::shared_ptr<const ParameterDictionary> dictionary);
    const ParameterDictionary &parameterDictionary() const;

    // Identity and state.
    virtual DriveReply *refreshIdentity();
    virtual DriveReply *readStatus();
    // Parameters. readParameters() fills reply->parameters(); write-only parameters are
    // skipped (not an error). writeParameters() validates ALL values first (nothing is sent
    // if one is bad), then writes each, reads it back and fills reply->writeResults(); it
    // finishes with VerifyMismatch / the first error if any parameter failed.
    virtual DriveReply *readParameters(const QList<int> &indices);
    virtual DriveReply *writeParameters(const QList<ParameterWrite> &writes);
    // Live values: fills reply->samples() for the channel ids asked for.
    virtual DriveReply *readChannels(const QStringList &channelIds);
    // The least time one readChannels(channelIds) takes on the wire, in µs: its requests
    // and replies at the link's speed, the pauses the protocol imposes and a typical drive
    // latency (1 ms serial, 200 µs CAN: the simulator's). 1e6 / this is the most readings a
    // second the link carries: the trend's default rate. 0 when unknown.
    virtual double channelReadUs(const QStringList &channelIds) const
    {
        Q_UNUSED(channelIds);
        return 0.0;
    }
    // Alarms.
    virtual DriveReply *readAlarm();
    virtual DriveReply *clearAlarm();
    // Motion.
    virtual DriveReply *setEnabled(bool on);
    DriveReply *jog(qint32 speed);
    DriveReply *stop(bool emergency = false);
    virtual DriveReply *moveRelative(qint64 distance, qint32 speed);
    virtual DriveReply *moveAbsolute(qint64 target, qint32 speed);
    virtual DriveReply *home(bool positiveFirst);
    virtual DriveReply *setPosition(qint64 position);
    // EEPROM (servo-modbus).
    virtual DriveReply *eeOperation(EeOperation op);

    // The jog lease.
    void renewJogLease();
    bool isJogging() const { return m_jogging; }
    // How long the drive keeps moving without its host before it stops by itself (servo-can:
    // 2000 ms without a keep-alive); 0 when it has no such watchdog.
    virtual int watchdogMs() const { return 0; }
    int jogLeaseMs() const { return m_jogLeaseMs; }
    void setJogLeaseMs(int ms) { m_jogLeaseMs = ms; }

    // Validation against parameterDictionary() (known index, range, not read-only); no I/O.
    // validateWrites() returns the first problem (nothing may be sent if there is one).
    Error validateWrite(const ParameterWrite &write) const;
    Error validateWrites(const QList<ParameterWrite> &writes) const;

signals:
    void statusChanged(const dd::DriveStatus &status);
    void alarmChanged(int code);               // 0 = cleared
    void jogLeaseExpired();                    // the axis was stopped by the lease
    void jogEnded(const dd::JogEnd &end);      // after the stop of a jog, or a lost link
    void stopRequested(bool emergency);        // stop() was called, by anyone (a step test aborts)
    void connectionLost(const dd::Error &why); // the link went away

protected:
    virtual DriveReply *doJog(qint32 speed);
    virtual DriveReply *doStop(bool emergency);

    DriveReply *newReply();
    DriveReply *finishedReply(const Error &error);
    DriveReply *notSupported(Capability c);
    void setIdentity(const DriveIdentity &identity) { m_identity = identity; }
    DriveIdentity &mutableIdentity() { return m_identity; }
    // Merge a new state; emits statusChanged / alarmChanged when something changed.
    void updateStatus(const DriveStatus &status);
    // Ends the jog lease without a stop (the link is gone, or a stop is already underway).
    void endJogLease();
    // The link is gone: ends the jog lease and, if a jog was running, emits jogEnded() (the
    // drive's watchdog, if it has one, stops the axis).
    void endJogLeaseLinkLost(const Error &why);

private:
    void onJogLeaseTimeout();
    JogEnd describeStop(const Error &stopError, bool leaseExpired) const;

    DriveIdentity m_identity;
    DriveStatus m_status;
    std::shared_ptr<const ParameterDictionary> m_dictionary;
    QTimer m_jogLease;
    bool m_jogging = false;
    bool m_leaseStopping = false; // stop() called by the lease timer
    int m_jogLeaseMs = 300;
};

} // namespace dd
