#pragma once

#include "core/protocol/modbus/modbusrtu.h"
#include "core/protocol/modbus/modbusrtuparser.h"
#include "core/protocol/servomodbus/servomodbus.h"
#include "sim/bench/simfamilies.h"
#include "sim/bus/simserialdevice.h"
#include "sim/motor/loopgainparameter.h"
#include "sim/motor/motormodel.h"

#include <QJsonObject>
#include <array>
#include <optional>

namespace dd {

// A simulated `servo-modbus` drive (docs/protocols/servo-modbus.md) on a SimSerialBus.
//
// Speaks the drive side of Modbus RTU with the codec's stream parser: 0x03 reads of 1..20
// registers in the DP monitor block (0x0000..0x0017, fed from a MotorModel) or the PA block
// (0x0064..0x009F), 0x10 writes of 1..20 PA registers, and the EE operations in the format
// its firmware (PA2) supports. Behaviour where the seed is silent (documented choices):
//  - Exceptions (code 0x04, the only one the seed lists) for: a range outside one block,
//    a count of 0 or above 20, an EE code outside 1..5, the EE format the firmware lacks.
//    The address byte of an exception reply is 0x01, as the seed says (config option:
//    the drive's own address). A frame with an unknown function gets no reply.
//  - A request to this drive's address whose CRC fails gets the seed's error reply
//    [0x01][function | 0x80][0x04] (驱动器在对接收的数据进行校验后，若检测出错误 … 若读操作
//    校验出错，则出错码为读操作功能码+0x80; docs/protocols/servo-modbus.md, "Exceptions").
//    A damaged frame for another address, the broadcast or with an unknown function code
//    gets no reply. The frame is delimited by the RTU silence and the function's length.
//  - Broadcast (address 0): writes and EE operations are carried out, nothing is answered.
//  - PA2 (firmware) is read-only: writes to it are accepted and ignored.
//  - The address the drive answers to is PA51 as loaded at power-up (powerCycle() or
//    loadState()); a written PA51 takes effect after EE-Set and a power cycle.
//  - Legacy EE format (PA2 < 7050): the first 0x06 request starts the operation and is
//    answered with value 0x0000; repeats are answered 0x0000 while it runs (eeBusyUs,
//    default 300 ms) and with the op code once it has finished (then the drive is idle
//    again). New format (PA2 >= 7050): carried out at once, the 0x10 echo answers.
//  - EE-Set: EEPROM := working set. EE-rd: working := EEPROM. EE-bA: backup := working.
//    EE-rS: working := backup. EE-dEF: working and EEPROM := factory defaults.
//  - Units of the DP registers: speed and speed command r/min; torque and torque command
//    % of rated; current and phase currents 0.01 A; position pairs in encoder counts
//    split by the position rule (default binary words); DP-APo counts within one turn;
//    DP-Frq kpulse/s; DP-Cnt = PA4 (control mode); DP-Err the alarm code; DP-oUt bit 0
//    servo ready, bit 1 alarm; DP-Cod the UVW state 1..6; the rest 0.
class SimServoModbusDrive : public SimSerialDevice
{
public:
    struct Config
    {
        int address = 1; // PA51 at power-up
        int baud = 19200;
        quint16 firmware = 7051;           // PA2; below 7050 selects the legacy EE format
        qint64 eeBusyUs = 300000;          // how long a legacy EE operation runs
        bool exceptionAddressFixed = true; // seed: exception replies carry address 0x01
        servomodbus::PositionPairRule positionRule = servomodbus::PositionPairRule::BinaryWords;
        bool demoMotion = false;  // run a slow back-and-forth speed profile
        double resonanceHz = 0.0; // > 0: a compliant load resonating here
        MotorModel::Config motor;
    };

    static constexpr int ParameterCount = servomodbus::ParameterCount;
    using ParameterArray = std::array<quint16, ParameterCount>;

    SimServoModbusDrive();
    explicit SimServoModbusDrive(const Config &config);
    // The family's entry in the simulator table (sim/bench/simfamilies.h).
    static std::unique_ptr<SimSerialDevice> create(const SimDeviceSpec &spec, Error *error);

    // SimSerialDevice
    QList<QByteArray> onBusBytes(const QByteArray &bytes, qint64 nowUs) override;
    int baud() const override { return m_baud; }
    QString describe() const override;
    void advanceTo(qint64 nowUs) override;

    const Config &config() const { return m_config; }
    void setBaud(int baud) { m_baud = baud; }
    int address() const { return m_address; } // the address it answers to
    void setFirmware(quint16 pa2) { m_params[servomodbus::FirmwareParameter] = pa2; }
    void setExceptionAddressFixed(bool fixed) { m_config.exceptionAddressFixed = fixed; }
    void setEeBusyUs(qint64 us) { m_config.eeBusyUs = us < 0 ? 0 : us; }

    // Registers as the host would read them (monitor values at the last advanceTo()).
    quint16 parameter(int n) const;
    void setParameter(int n, quint16 value); // as if written over the bus
    quint16 eepromParameter(int n) const;
    quint16 backupParameter(int n) const;
    const ParameterArray &parameters() const { return m_params; }
    static ParameterArray factoryDefaults(const Config &config);
    // Which parameters the simulated closed loop reads (the simulator's model, docs/tuning.md;
    // the seed names no gain parameter): PA5 speed-loop gain (Hz, 40), PA6 speed-loop integral
    // gain (1/s, 30), PA7 position-loop gain (1/s, 60), PA8 speed feed-forward (%, 100), PA9
    // torque (acceleration) feed-forward (%, 100).
    static const QList<LoopGainParameter> &loopGainParameters();
    quint16 monitorRegister(int reg) const;

    // The drive's side of the world.
    MotorModel &motor() { return m_motor; }
    // The servo-on (SON) control input of the demo: the drive's power stage follows it, and
    // the demo profile runs only while it is on (a disabled servo does not run).
    void setServoOnInput(bool on);
    bool servoOnInput() const { return m_servoOnInput; }
    void setAlarm(int code);
    int alarm() const { return m_motor.alarmCode(); }
    // Power cycle: working set := EEPROM, address := PA51, EE state reset.
    void powerCycle();

    // EE state.
    bool eeRunning() const { return m_ee.has_value() && !m_eeFinished; }
    int eeOperationsCompleted() const { return m_eeCompleted; }
    std::optional<servomodbus::EeOp> lastEeOperation() const { return m_lastEe; }

    // Counters (tests).
    quint64 requestsAnswered() const { return m_answered; }
    quint64 exceptionsSent() const { return m_exceptions; }
    quint64 broadcastsHandled() const { return m_broadcasts; }
    quint64 framesIgnored() const { return m_ignored; }
    quint64 checksumErrors() const { return m_checksumErrors; }
    // Line noise on the way to the drive (tests): the next `count` requests addressed to it
    // arrive with one bit of their last byte flipped (a bad CRC).
    void damageIncomingRequests(int count) { m_damageRequests = count < 0 ? 0 : count; }

    // --state files of drivedesk-sim: working set, EEPROM, backup area, alarm, address.
    QJsonObject saveState() const;
    bool loadState(const QJsonObject &state, QString *error = nullptr);

private:
    QList<QByteArray> handleFrame(const QByteArray &adu, qint64 nowUs);
    QList<QByteArray> answerDamagedRequest();
    QByteArray exceptionReply(const modbusrtu::Request &request);
    QByteArray handleRead(const modbusrtu::Request &request);
    QByteArray handleWrite(const modbusrtu::Request &request, bool broadcast);
    QByteArray handleEe(const modbusrtu::Request &request, servomodbus::EeFormat format, bool broadcast, qint64 nowUs);
    void startEe(servomodbus::EeOp op, qint64 nowUs);
    void applyEe(servomodbus::EeOp op);
    void updateDemo(qint64 nowUs);
    bool legacyFirmware() const;

    Config m_config;
    int m_baud = 19200;
    int m_address = 1;
    ParameterArray m_params{};
    ParameterArray m_eeprom{};
    ParameterArray m_backup{};
    MotorModel m_motor;
    bool m_servoOnInput = true;
    ModbusRtuStreamParser m_parser{ModbusRtuStreamParser::Mode::Requests};
    qint64 m_lastBytesUs = -1;
    QByteArray m_frameBytes; // since the last RTU silence: a request whose CRC may fail
    int m_damageRequests = 0;
    quint64 m_checksumErrors = 0;
    qint64 m_nowUs = 0;

    std::optional<servomodbus::EeOp> m_ee; // the legacy operation started / finished
    qint64 m_eeDoneAtUs = 0;
    bool m_eeFinished = false;
    int m_eeCompleted = 0;
    std::optional<servomodbus::EeOp> m_lastEe;

    quint64 m_answered = 0;
    quint64 m_exceptions = 0;
    quint64 m_broadcasts = 0;
    quint64 m_ignored = 0;
};

} // namespace dd
