#pragma once

#include "core/drive/drive.h"
#include "core/drive/shuoke/shuoketransport.h"
#include "core/protocol/shuoke/shuokecommands.h"

#include <QHash>
#include <QPointer>
#include <memory>
#include <optional>

namespace dd {

struct ShuokeParameter;
class WriteVerification;

// A Shuoke stepper drive (M6505 closed loop, M4505 / M4505S open loop;
// docs/protocols/shuoke.md) on any of the four framings, through a ShuokeTransport.
//
// Model: "shuoke.model" or, on auto, detected by refreshIdentity() (0x58 answers only on
// the M6505, 0x30 on the M6505 and M4505S). Until it is known every command is allowed and
// the drive's own "unknown command" (0x03) answer is reported. Commands a known model
// lacks are refused before sending (NotSupported, with the reason).
//
// Every request is checked first: model, framing (CAN carries at most 5 data bytes, PLC
// only mapped commands) and shuoke::validateRequestData (ranges): nothing goes on the wire
// for a value the drive would refuse.
//
// Parameters: index = SET command code (ShuokeParameter). A write is read back with the
// GET command and compared. Write-only settings cannot be read back: the drive keeps the
// last value it wrote (lastWritten()), readParameters() skips them and lists them in
// info "notReadable", with their last written values in info "lastWritten" (a map
// "index" -> value). A write of the baud code (0x24) switches a serial link to the new
// rate before reading back (the drive changes its rate after its reply).
//
// Channels: speed 0x36, position 0x37, relative-position 0x39, status 0x3B (bits: 0
// running, 1 left limit, 2 origin, 3 right limit, 4 enable input), inputs 0x42 (IO1..IO5),
// control-inputs 0x43 (pulse, direction, enable, F1, F2), closed-loop-position 0x58,
// closed-loop-relative-position 0x5A, and on the M6505 position-error = 0x37 - 0x58
// (commanded pulses minus encoder feedback; meaningful when both counters share their
// zero, as after homing).
//
// Motion: jog = 0x33 (signed speed), stop = 0x3D, emergency stop = 0x3C, relative move =
// 0x31, absolute move = 0x57 on the M6505 (closed-loop target), otherwise 0x37 is read and
// the difference moved with 0x31. The seed's moves have no speed of their own: they run at
// the stored maximum speed (0x27 / 0x28, parameter max-speed). A move with speed > 0 reads
// the stored value (0x28; unreadable: the move is refused), sets the move's speed (0x27) and,
// once readStatus() finds the axis at rest after the move, writes the stored value back
// (info "maxSpeedRestored"): a move leaves the drive's settings as they were, as long as its
// state is read until the end (the GUI's poll, the CLI's move without --no-wait). speed <= 0
// moves at the stored maximum speed and changes nothing. Home = 0x3E. The
// drive has no enable command and no alarm register: enable is NotSupported, readAlarm()
// reports the limit-switch bits and the last failure code this drive answered.
// Stops (0x3C / 0x3D) are urgent requests: they go ahead of everything waiting on the link
// (a trend's reads), right after the request on the wire. So that a motion command still
// waiting cannot restart the axis after such a stop, the stop is sent once more behind it,
// and a motion sequence under way (speed, then move) sends no further motion command after
// a stop: it finishes with Cancelled.
class ShuokeDrive : public Drive
{
    Q_OBJECT
public:
    ShuokeDrive(ShuokeTransport *transport, int address, QObject *parent = nullptr);
    ~ShuokeDrive() override;

    Family family() const override { return Family::Shuoke; }
    Capabilities capabilities() const override;
    QList<ChannelInfo> channels() const override;
    QString unsupportedReason(Capability c) const override;

    DriveReply *refreshIdentity() override;
    DriveReply *readStatus() override;
    DriveReply *readParameters(const QList<int> &indices) override;
    DriveReply *writeParameters(const QList<ParameterWrite> &writes) override;
    DriveReply *readChannels(const QStringList &channelIds) override;
    double channelReadUs(const QStringList &channelIds) const override;
    DriveReply *readAlarm() override;
    DriveReply *moveRelative(qint64 distance, qint32 speed) override;
    DriveReply *moveAbsolute(qint64 target, qint32 speed) override;
    DriveReply *home(bool positiveFirst) override;
    DriveReply *setPosition(qint64 position) override;

    // The model, when configured or detected.
    std::optional<shuoke::Model> model() const { return m_model; }
    void setModel(std::optional<shuoke::Model> model);
    // The parameters this drive has (all of them while the model is unknown).
    QList<int> parameterIndices() const;
    std::optional<qint64> lastWritten(int index) const;
    int lastFailureCode() const { return m_lastFailure; }
    ShuokeTransport *transport() const { return m_transport; }

    // 0x22: the new address takes effect when the drive restarts.
    DriveReply *changeAddress(int newAddress);
    // Any command: info "replyAddress", "replyCommand", "replyData" (QByteArray). With
    // `validate` false the request skips the checks above (tests, experts). `address` -1:
    // this drive; a broadcast stop (0x3C / 0x3D) expects no reply.
    DriveReply *sendCommand(quint8 command, const QByteArray &data = {}, bool validate = true, int address = -1);
    // Why `command` with `dataLength` bytes cannot be sent to this drive; empty when it can.
    QString commandUnavailable(quint8 command, int dataLength = -1) const;

protected:
    DriveReply *doJog(qint32 speed) override;
    DriveReply *doStop(bool emergency) override;

private:
    using Handler = ShuokeTransport::Handler;
    struct Step
    {
        quint8 command = 0;
        QByteArray data;
    };

    // All checks of a request; an error means nothing may be sent.
    Error check(quint8 command, const QByteArray &data) const;
    Error checkSteps(const QList<Step> &steps) const;
    // A stop command goes ahead of everything waiting on the link unless `behindQueued`.
    void exchange(DriveReply *reply, quint8 command, const QByteArray &data, Handler done, bool expectReply = true,
                  bool behindQueued = false);
    // Runs `steps` one after another; finishes `reply` with the first error or none. A
    // motion command is not sent once a stop has come since `stopsBefore` (= m_stops when
    // the operation began).
    void runSteps(DriveReply *reply, QList<Step> steps, quint64 stopsBefore);
    DriveReply *simpleCommands(const QList<Step> &steps);
    std::optional<qint32> decodeInt(const QByteArray &data) const;
    QByteArray int32(qint64 v) const;
    shuoke::ByteOrder byteOrder() const;
    bool modelIs(shuoke::Model m) const { return m_model && *m_model == m; }
    bool maySupport(quint8 command, int length = -1) const;
    void noteFailure(const Error &e);

    // refreshIdentity() helpers
    void detectModel(DriveReply *reply, std::function<void()> next);
    // readParameters / writeParameters helpers (shuokedriveparameters.cpp)
    Error checkParameterWrite(const ParameterWrite &w, const ShuokeParameter **param) const;
    void readOneParameter(DriveReply *reply, const ShuokeParameter &p, std::function<void(const Error &, qint64)> done);
    void writeNext(DriveReply *reply, QList<ParameterWrite> writes, int at,
                   std::shared_ptr<WriteVerification> verification);
    // readChannels helpers (shuokedrivechannels.cpp)
    QList<quint8> channelCommands(const QStringList &ids) const;
    void fillSamples(DriveReply *reply, const QStringList &ids, const QHash<quint8, QByteArray> &data) const;
    bool channelAvailable(const QString &id) const;
    void applyStatusBits(DriveReply *reply, const QByteArray &statusData, std::optional<qint64> position);
    // The stored max-speed a move at `speed` replaces: read and kept, then `next`.
    void keepMaxSpeed(DriveReply *reply, qint32 speed, std::function<void()> next);
    // From readStatus(): the kept max-speed written back once the move is over, then `done`.
    void restoreMaxSpeedAtRest(DriveReply *reply, std::function<void()> done);

    QPointer<ShuokeTransport> m_transport;
    std::optional<shuoke::Model> m_model;
    QHash<int, qint64> m_lastWritten;
    int m_lastFailure = 0;
    int m_motionQueued = 0; // motion commands handed to the link, not answered yet
    quint64 m_stops = 0;    // stops so far
    // The sign of the last motion commanded (jog, relative move; 0: unknown). 0x36 reports
    // the speed's magnitude (the seed marks only the position signed): the speed channel
    // takes its direction from this.
    int m_commandedDirection = 0;
    // The stored max-speed a move's speed replaced, until written back (keepMaxSpeed()).
    std::optional<quint32> m_maxSpeedToRestore;
    bool m_restoreSeenRunning = false; // the axis was seen moving since the last move began
    int m_restoreRestReads = 0;        // status reads at rest since then
};

} // namespace dd
