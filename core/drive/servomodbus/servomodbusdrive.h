#pragma once

#include "core/drive/drive.h"
#include "core/drive/writeverification.h"
#include "core/link/modbuslink.h"
#include "core/protocol/servomodbus/servomodbus.h"

#include <QPointer>
#include <QVariantMap>
#include <optional>

namespace dd {

// Settings of a servo-modbus drive where the seed is silent (ConnectionSettings::options).
struct ServoModbusOptions
{
    // "servo-modbus.positionRule": binary (default) | decimal10000 | decimal100000
    servomodbus::PositionPairRule positionRule = servomodbus::PositionPairRule::BinaryWords;
    // "servo-modbus.eeFormat": auto (from PA2, default) | legacy | new
    servomodbus::EeFormatChoice eeFormat = servomodbus::EeFormatChoice::Auto;
    int eeTimeoutMs = 10000;     // "servo-modbus.eeTimeoutMs": legacy format, until done
    int eePollMs = 50;           // "servo-modbus.eePollMs": legacy format, between polls
    int eeReplyTimeoutMs = 3000; // new format: the drive may answer after the EEPROM write

    // Reads the options above; unknown values give an InvalidArgument error naming the key.
    static ServoModbusOptions fromMap(const QVariantMap &options, Error *error = nullptr);
};

// A `servo-modbus` drive (docs/protocols/servo-modbus.md) on a ModbusLink.
//  - Identity: PA2 (firmware, chooses the EE format) and PA51 (address).
//  - Parameters PA0..PA59: reads planned by servomodbus::planReads (<= 20 registers per
//    request, PA0..PA59 in three), writes as 0x10 runs of consecutive parameters, then
//    read back and compared. Values are int16 (the dictionary may say otherwise).
//  - Channels: the DP monitor registers, read in as few requests as the asked-for set
//    allows (position pairs combined by the position rule, raw halves also offered).
//  - Alarm: DP-Err (0x0013). EE operations in both formats, legacy polled until done.
// The seed has no motion, enable, stop or alarm-clear command: those are NotSupported with
// a reason (the axis runs from the drive's own control inputs).
class ServoModbusDrive : public Drive
{
    Q_OBJECT
public:
    ServoModbusDrive(ModbusLink *link, int address, const ServoModbusOptions &options = {}, QObject *parent = nullptr);

    Family family() const override { return Family::ServoModbus; }
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
    DriveReply *eeOperation(EeOperation op) override;

    const ServoModbusOptions &options() const { return m_options; }
    void setOptions(const ServoModbusOptions &options) { m_options = options; }
    std::optional<quint16> firmware() const { return m_firmware; } // PA2 once read
    ModbusLink *link() const { return m_link; }

private:
    Error checkLink() const;
    Error checkWrites(const QList<ParameterWrite> &writes) const;
    qint64 parameterValue(int index, quint16 raw) const;
    void runEe(DriveReply *reply, servomodbus::EeOp op, servomodbus::EeFormat format);
    void pollLegacyEe(DriveReply *reply, servomodbus::EeOp op, qint64 deadlineMs, int polls);
    void writeThenVerify(DriveReply *reply, const QList<ParameterWrite> &writes);
    // Reads back every write the drive did not refuse and reports each (WriteVerification).
    void verifyWrites(DriveReply *reply, const QList<ParameterWrite> &writes, const QHash<int, Error> &writeErrors);
    WriteVerification::Check verificationCheck(const ParameterWrite &w, const Error &writeError,
                                               const QHash<quint16, quint16> &regs, const Error &readError) const;

    QPointer<ModbusLink> m_link;
    ServoModbusOptions m_options;
    std::optional<quint16> m_firmware;
};

} // namespace dd
