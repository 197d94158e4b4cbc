#pragma once

#include "core/drive/drive.h"
#include "core/drive/writeverification.h"
#include "core/protocol/servocan/servocan.h"

#include <QPointer>
#include <functional>
#include <memory>

namespace dd {

class CanLink;
class LinkReply;
class ServoCanStationTracker;

// One `servo-can` drive (station 0..99) on a CanLink (docs/protocols/servo-can.md).
//
// Replies: only 0x12 reads are answered. They are pipelined through the link's window (a
// full parameter backup puts all 220 reads in flight) and matched by station, read type and
// parameter index, so they may come back in any order. Every other command is sent without
// waiting and verified by what can be read back:
//   - parameter writes (0x15): the parameter is read back; a mismatch rewrites it, up to
//     1 + the link's retries times, then the write finishes with VerifyMismatch;
//   - jog / moves (0x20, 0x21, 0x22): the reply finishes when a heartbeat shows the axis
//     running (or already on the target), or with DriveException after motionStartMs();
//   - set position (0x50): position read back (0xFD) when the axis is idle;
//   - clear alarm (0x81): alarm code read back (0xAA) until 0 or alarmClearMs();
//   - enable (0x25): not readable (the heartbeat has no enable bit); it finishes when the
//     frame is on the bus; status().enabled is what was last commanded. A disable goes out
//     at once like a stop (an urgent request: ahead of reads waiting for the window) and
//     once more behind them, so that a queued enable or motion command cannot re-enable;
//   - stop (0x26 / 0x28): finishes when a heartbeat of the station arrives after it (the
//     drive is alive, so it heard the stop), or with Timeout after stopConfirmMs(): then its
//     watchdog (watchdogMs(), 2 s without keep-alive) is what stops the axis. A station that
//     goes offline during a jog is stopped the same way (jogEnded() says which happened).
// A stop jumps the queue: it is written at once (ahead of reads waiting for the link's
// window) and once more behind everything already queued, so that a motion command still
// waiting in the queue cannot restart the axis after the stop.
// Keep-alive: this drive takes its station's motion lease (ServoCanStationTracker) when it
// sends a jog or a move and gives it up when it sends a stop or a disable; the tracker sends
// the keep-alive only while the lease is held (docs/reliability.md).
// Status: online / running / position come from the heartbeats (via the link's
// ServoCanStationTracker), the alarm code from 0x05 frames and 0xAA reads.
//
// Units: speeds in r/min (the seed's "正 100 转" example), positions in encoder counts.
// Emergency stop: 0x28 by default (stop, then torque off: IEC 60204-1 stop category 1),
// or 0x26 (stop and hold the shaft: for vertical axes without a brake) with
// setEmergencyStopHolds(true) — option "servo-can.emergencyStop" = "disable" | "hold".
// Confirmed reads (option "servo-can.confirmReads"): each parameter is read until three
// answers agree (up to eight reads). Real CAN hardware never delivers a damaged frame (CRC), so this is off by
// default; it defends against a drive (or a simulator) that answers wrong values.
class ServoCanDrive : public Drive
{
    Q_OBJECT
public:
    ServoCanDrive(CanLink *link, ServoCanStationTracker *tracker, int station, QObject *parent = nullptr);
    ~ServoCanDrive() override;

    Family family() const override { return Family::ServoCan; }
    Capabilities capabilities() const override;
    QList<ChannelInfo> channels() const override;
    QString unsupportedReason(Capability c) const override;

    quint8 station() const { return m_station; }
    static QList<int> allParameterIndices(); // 0..219

    DriveReply *refreshIdentity() override;
    DriveReply *readStatus() override;
    DriveReply *readParameters(const QList<int> &indices) override;
    DriveReply *writeParameters(const QList<ParameterWrite> &writes) override;
    DriveReply *readChannels(const QStringList &channelIds) override;
    double channelReadUs(const QStringList &channelIds) const override;
    DriveReply *readAlarm() override;
    DriveReply *clearAlarm() override;
    DriveReply *setEnabled(bool on) override;
    DriveReply *moveRelative(qint64 distance, qint32 speed) override;
    DriveReply *moveAbsolute(qint64 target, qint32 speed) override;
    DriveReply *setPosition(qint64 position) override;

    bool emergencyStopHolds() const { return m_emergencyHolds; }
    void setEmergencyStopHolds(bool hold) { m_emergencyHolds = hold; }
    bool confirmReads() const { return m_confirmReads; }
    void setConfirmReads(bool on) { m_confirmReads = on; }
    int motionStartMs() const { return m_motionStartMs; }
    void setMotionStartMs(int ms) { m_motionStartMs = ms; }
    int alarmClearMs() const { return m_alarmClearMs; }
    void setAlarmClearMs(int ms) { m_alarmClearMs = ms; }
    int stopConfirmMs() const { return m_stopConfirmMs; }
    void setStopConfirmMs(int ms) { m_stopConfirmMs = ms; }
    int watchdogMs() const override;

    // The frame doStop(emergency) sends (for the backend's stopAll()).
    CanFrameData stopFrame(bool emergency) const;

protected:
    DriveReply *doJog(qint32 speed) override;
    DriveReply *doStop(bool emergency) override;

private:
    using ReadDone = std::function<void(const Error &error, qint32 value)>;
    using Done = std::function<void(const Error &error)>;

    // One 0x12 read (retried by the link on timeout); value is the int16 parameter or int32.
    void readRaw(servocan::ReadType type, quint8 index, const ReadDone &done);
    // A parameter read; with confirmReads() read until three answers agree.
    void readParameterValue(quint8 index, const ReadDone &done);
    struct ConfirmState;
    void confirmRead(quint8 index, const std::shared_ptr<ConfirmState> &state);
    // Frames without a reply, queued in order with the reads.
    // A frame in order with the reads; `urgent`: ahead of the reads waiting for the window.
    void sendCommand(const CanFrameData &frame, const QString &note, const Done &done = {}, bool urgent = false);
    void writeOne(const ParameterWrite &w, int attempt, DriveReply *reply,
                  const std::function<void(const WriteVerification::Check &)> &done);
    // Waits for a heartbeat, arriving from now on, for which `pred` holds.
    void awaitHeartbeat(const std::function<bool(quint8 state, qint32 position)> &pred, int timeoutMs,
                        const Done &done);
    DriveReply *startMotion(const QList<CanFrameData> &frames, const QString &what,
                            const std::function<bool(quint8, qint32)> &started);
    void pollAlarmCleared(DriveReply *reply, qint64 deadlineMs);

    void onHeartbeat(int station, quint8 state, qint32 position);
    void onAlarm(int station, int code);
    void onOnline(int station, bool online);
    void onLinkClosed(const Error &why);
    void setAlarmCode(int code);
    void setEnabledState(bool on);
    Error linkClosedError() const;

    QPointer<CanLink> m_link;
    QPointer<ServoCanStationTracker> m_tracker;
    quint8 m_station;
    bool m_emergencyHolds = false;
    bool m_confirmReads = false;
    int m_motionStartMs = 300;
    int m_alarmClearMs = 300;
    int m_stopConfirmMs = 150; // five heartbeat periods
    quint64 m_stopsSent = 0;   // stops and disables: a motion command queued before one takes no lease
};

} // namespace dd
