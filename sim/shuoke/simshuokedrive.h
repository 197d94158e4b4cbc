#pragma once

#include "core/protocol/shuoke/shuokecommands.h"
#include "core/protocol/shuoke/shuokeframe.h"
#include "core/protocol/shuoke/shuokevalues.h"
#include "sim/shuoke/simshuokeaxis.h"

#include <QByteArray>
#include <QHash>
#include <QJsonObject>
#include <QList>
#include <optional>

namespace dd {

// The drive side of the Shuoke command set (docs/protocols/shuoke.md), independent of the
// framing: the adapters SimShuokeSerialDevice (RTU, ASCII, PLC) and SimShuokeCanDevice
// decode the wire into Frames, call handle() and encode what it returns.
//
// What it models:
//  - the model (M6505 / M4505 / M4505S): commands the model lacks get failure 0x03;
//  - address (1..247; 0 and 255 both broadcast unless Config::broadcasts says otherwise),
//    baud code, CAN bitrate code, CAN frame format, all settings including the write-only
//    ones, IO-substitution entries, speed step F;
//  - failure replies: 0x01 wrong data length, 0x02 checksum (reported by the adapters),
//    0x03 unknown command (or one the model / the medium does not take), 0x04 value out of
//    range (shuoke::validateRequestData, in the drive's byte order), 0x05 command not
//    allowed as broadcast;
//  - broadcasts: 0x3C / 0x3D act without a reply, 0x21 is answered;
//  - address changes (0x22), CAN settings (0x4A, 0x4B) and the factory reset (0x47) take
//    effect at the next powerCycle(); a new baud code (0x24) right after the reply;
//  - serial rate: 9600 for the first Config::powerUpWindowMs (2 s) after power-up, then the
//    configured baud code (set the window to 0 to start at the configured rate);
//  - the 50 ms rule: on serial and PLC a command arriving less than Config::minCommandGapMs
//    after the previous one is ignored (no reply; counted by tooSoonCount());
//  - motion through SimShuokeAxis: jog, moves (open and closed loop, geared 0x56 with the
//    gear setting), stops, limits, homing, speed steps (0x44..0x46). Stored without effect
//    on the model: start / stop speeds, encoder and motion direction, error correction,
//    encoder tolerances, IO substitution entries.
// Times are the bus clock in microseconds.
class SimShuokeDrive
{
public:
    enum class Medium { Serial, Can, Plc };

    struct Config
    {
        shuoke::Model model = shuoke::Model::M6505;
        quint8 address = 1;
        int baudCode = 6; // 9600
        int canBitrateCode = shuoke::kDefaultCanBitrateCode;
        bool canExtended = false;
        shuoke::ByteOrder byteOrder = shuoke::ByteOrder::LittleEndian;
        QList<quint8> broadcasts{shuoke::kBroadcastZero, shuoke::kBroadcastAllOnes};
        quint16 plcBase = 0;
        int powerUpWindowMs = 2000; // 9600 baud after power-up
        // Serial and PLC: a command that arrives sooner than this after the previous one is
        // not taken (the V1.5 note "leave at least 50 ms between commands"); 0: no limit.
        int minCommandGapMs = 50;
        bool enableInput = true;
        quint8 inputs = 0;           // 0x42 bits IO1..IO5
        quint8 controlInputs = 0x04; // 0x43 bits pulse, dir, enable, F1, F2
        SimShuokeAxis::Switches switches;
    };

    SimShuokeDrive();
    explicit SimShuokeDrive(const Config &config);

    // The reply to `request` arriving over `medium` at `nowUs`; nullopt when the drive stays
    // silent (not addressed to it, or a broadcast without a reply).
    std::optional<shuoke::Frame> handle(const shuoke::Frame &request, Medium medium, qint64 nowUs);
    // A failure reply from this drive.
    shuoke::Frame failure(quint8 command, quint8 code) const;
    // Whether a frame to `address` concerns this drive (its own or a broadcast address).
    bool isAddressed(quint8 address) const;

    void advanceTo(qint64 nowUs);
    // Restart: pending address / CAN settings / factory reset apply, 9600 for the window.
    void powerCycle(qint64 nowUs);
    // The serial rate at `nowUs` (9600 during the power-up window).
    int serialBaud(qint64 nowUs) const;

    const Config &config() const { return m_config; }
    quint8 address() const { return m_config.address; }
    shuoke::Model model() const { return m_config.model; }
    shuoke::ByteOrder byteOrder() const { return m_config.byteOrder; }
    bool isBroadcast(quint8 address) const;
    // The ENA input: without it the power stage is off and the axis does not move.
    void setEnableInput(bool on);
    quint16 plcBase() const { return m_config.plcBase; }
    bool skipsCrcCheck() const { return m_settings.value(shuoke::CmdSkipCrcCheck) != 0; }
    bool fixedLengthReplies() const { return m_settings.value(shuoke::CmdFixedLengthReplies) != 0; }
    std::optional<quint8> pendingAddress() const { return m_pendingAddress; }

    // Every stored setting by its SET command (0x24 baud code, 0x25.., write-only ones).
    qint64 setting(quint8 setCommand) const { return m_settings.value(setCommand); }
    void setSetting(quint8 setCommand, qint64 value);
    QByteArray ioSubstitution(int index) const { return m_ioSubstitution.value(index); }

    SimShuokeAxis &axis() { return m_axis; }
    const SimShuokeAxis &axis() const { return m_axis; }

    // Diagnostics: requests handled (addressed to this drive) and their arrival times.
    int requestCount() const { return m_requestCount; }
    int tooSoonCount() const { return m_tooSoon; }
    const QList<qint64> &requestTimesUs() const { return m_requestTimes; }
    QList<quint8> requestCommands() const { return m_requestCommands; }

    // --state: configuration, settings and positions as JSON.
    QJsonObject saveState() const;
    bool loadState(const QJsonObject &state, QString *error = nullptr);

    static QString mediumName(Medium medium);

private:
    void resetSettings();
    void applySettingsToAxis();
    std::optional<shuoke::Frame> execute(const shuoke::Frame &request, Medium medium);
    std::optional<shuoke::Frame> executeMotion(const shuoke::Frame &request);
    QByteArray u32(qint64 v) const;
    QByteArray i32(qint64 v) const;
    qint32 dataInt(const QByteArray &data) const;
    quint32 dataUInt(const QByteArray &data) const;

    Config m_config;
    SimShuokeAxis m_axis;
    QHash<quint8, qint64> m_settings;
    QHash<int, QByteArray> m_ioSubstitution;
    std::optional<quint8> m_pendingAddress;
    std::optional<int> m_pendingCanBitrate;
    std::optional<bool> m_pendingCanExtended;
    bool m_pendingFactoryReset = false;
    qint64 m_powerOnUs = 0;
    qint64 m_nowUs = 0;
    int m_requestCount = 0;
    int m_tooSoon = 0;
    qint64 m_lastSerialRequestUs = -1;
    QList<qint64> m_requestTimes;
    QList<quint8> m_requestCommands;
};

} // namespace dd
