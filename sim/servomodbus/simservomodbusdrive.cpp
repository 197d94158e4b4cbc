#include "sim/servomodbus/simservomodbusdrive.h"

#include "core/common/mathconstants.h"
#include "core/link/wiretime.h"
#include "core/protocol/modbus/crc16.h"
#include "sim/bus/simlogging.h"

#include <QJsonArray>
#include <algorithm>
#include <cmath>

namespace dd {

namespace {
constexpr int PolePairs = 4; // electrical angle for the phase currents and UVW
constexpr double DemoRpm = 1000.0;

quint16 s16(double v)
{
    const double r = std::clamp(std::round(v), -32768.0, 32767.0);
    return static_cast<quint16>(static_cast<qint16>(r));
}

QJsonArray toJson(const SimServoModbusDrive::ParameterArray &a)
{
    QJsonArray out;
    for (quint16 v : a)
        out.append(int(qint16(v)));
    return out;
}

bool fromJson(const QJsonValue &v, SimServoModbusDrive::ParameterArray *out, const char *name, QString *error)
{
    const QJsonArray a = v.toArray();
    if (a.size() != SimServoModbusDrive::ParameterCount) {
        if (error)
            *error = QStringLiteral("state: \"%1\" must hold %2 values")
                         .arg(QLatin1String(name))
                         .arg(SimServoModbusDrive::ParameterCount);
        return false;
    }
    for (int i = 0; i < a.size(); ++i) {
        const int x = a.at(i).toInt(100000);
        if (x < -32768 || x > 65535) {
            if (error)
                *error = QStringLiteral("state: \"%1\"[%2] is not a 16-bit value").arg(QLatin1String(name)).arg(i);
            return false;
        }
        (*out)[size_t(i)] = static_cast<quint16>(x);
    }
    return true;
}
} // namespace

SimServoModbusDrive::SimServoModbusDrive()
    : SimServoModbusDrive(Config{})
{
}

SimServoModbusDrive::SimServoModbusDrive(const Config &config)
    : m_config(config)
    , m_baud(config.baud)
    , m_address(config.address)
    , m_motor(MotorModel::closedLoopConfig(config.motor, config.resonanceHz))
{
    m_params = factoryDefaults(config);
    m_params[servomodbus::AddressParameter] = static_cast<quint16>(config.address);
    m_eeprom = m_params;
    m_backup = m_params;
}

SimServoModbusDrive::ParameterArray SimServoModbusDrive::factoryDefaults(const Config &config)
{
    // The seed names no parameter but PA2 and PA51: distinct, harmless values elsewhere so
    // that a test notices a parameter read from the wrong register.
    ParameterArray a{};
    for (int n = 0; n < ParameterCount; ++n)
        a[size_t(n)] = static_cast<quint16>(100 + n);
    a[0] = 315; // PA0: the usual password of this class
    a[servomodbus::FirmwareParameter] = config.firmware;
    a[4] = 0; // PA4: control mode
    a[servomodbus::AddressParameter] = 1;
    for (const LoopGainParameter &g : loopGainParameters())
        a[size_t(g.index)] = static_cast<quint16>(g.defaultValue);
    return a;
}

const QList<LoopGainParameter> &SimServoModbusDrive::loopGainParameters()
{
    using R = LoopGainParameter::Role;
    static const QList<LoopGainParameter> table = {
        {5, R::SpeedKp, 40, 1, 1000},          {6, R::SpeedKi, 30, 0, 5000},           {7, R::PositionKp, 60, 0, 1000},
        {8, R::SpeedFeedforward, 100, 0, 100}, {9, R::TorqueFeedforward, 100, 0, 100},
    };
    return table;
}

QString SimServoModbusDrive::describe() const
{
    return QStringLiteral("servo-modbus addr %1 @ %2, firmware %3 (%4 EE format)")
        .arg(m_address)
        .arg(m_baud)
        .arg(m_params[servomodbus::FirmwareParameter])
        .arg(legacyFirmware() ? QStringLiteral("legacy") : QStringLiteral("new"));
}

bool SimServoModbusDrive::legacyFirmware() const
{
    return servomodbus::eeFormatForFirmware(m_params[servomodbus::FirmwareParameter]) == servomodbus::EeFormat::Legacy;
}

void SimServoModbusDrive::advanceTo(qint64 nowUs)
{
    if (nowUs < m_nowUs)
        return;
    m_nowUs = nowUs;
    updateDemo(nowUs);
    applyLoopGainParameters(
        loopGainParameters(), [this](int n) { return qint64(qint16(parameter(n))); }, &m_motor);
    m_motor.advanceTo(double(nowUs) / 1e6);
    if (m_ee && !m_eeFinished && nowUs >= m_eeDoneAtUs) {
        applyEe(*m_ee);
        m_eeFinished = true;
    }
}

void SimServoModbusDrive::setServoOnInput(bool on)
{
    m_servoOnInput = on;
    if (!on)
        m_motor.disable(); // the shaft coasts to rest
}

void SimServoModbusDrive::updateDemo(qint64 nowUs)
{
    // The demo drive follows its control inputs: SON on (and no alarm) switches the power
    // stage on; only then does the speed profile run.
    if (!m_config.demoMotion || !m_servoOnInput || m_motor.alarmCode() != 0)
        return;
    if (!m_motor.isEnabled())
        m_motor.enable();
    // 8 s cycle: forward 3 s, stop 1 s, reverse 3 s, stop 1 s.
    const double t = std::fmod(double(nowUs) / 1e6, 8.0);
    const double rpm = t < 3.0 ? DemoRpm : (t < 4.0 ? 0.0 : (t < 7.0 ? -DemoRpm : 0.0));
    const double target = rpm * m_motor.config().countsPerRev / 60.0;
    if (std::abs(m_motor.targetSpeed() - target) > 0.5)
        m_motor.runSpeed(target);
}

QList<QByteArray> SimServoModbusDrive::onBusBytes(const QByteArray &bytes, qint64 nowUs)
{
    advanceTo(nowUs);
    // RTU frames end with 3.5 quiet characters: bytes after a longer gap start afresh.
    const qint64 chunkStartUs = nowUs - qint64(WireTime::serialBytesUs(bytes.size(), m_baud, bitsPerChar()));
    const bool silenceBefore = m_lastBytesUs < 0
        || chunkStartUs - m_lastBytesUs > qint64(WireTime::modbusSilenceUs(m_baud, bitsPerChar()));
    if (silenceBefore) {
        m_parser.discardPending();
        m_frameBytes.clear();
    }
    m_lastBytesUs = nowUs;
    QByteArray heard = bytes;
    if (m_damageRequests > 0 && silenceBefore && !heard.isEmpty() && quint8(heard.at(0)) == m_address) {
        --m_damageRequests;
        heard.back() = char(heard.back() ^ 0x01);
    }
    m_frameBytes += heard;
    if (m_frameBytes.size() > ModbusRtuStreamParser::DefaultBufferCap)
        m_frameBytes.remove(0, m_frameBytes.size() - ModbusRtuStreamParser::DefaultBufferCap);
    m_parser.feed(heard);
    QList<QByteArray> replies;
    bool framed = false;
    while (m_parser.hasFrame()) {
        framed = true;
        replies += handleFrame(m_parser.takeFrame(), nowUs);
    }
    if (framed)
        m_frameBytes.clear();
    else
        replies += answerDamagedRequest();
    return replies;
}

QList<QByteArray> SimServoModbusDrive::answerDamagedRequest()
{
    // What arrived since the last silence, if it is a whole request to this drive by its
    // function's length and its CRC fails, gets the seed's error reply.
    if (m_frameBytes.size() < 2 || quint8(m_frameBytes.at(0)) != m_address)
        return {};
    const quint8 function = quint8(m_frameBytes.at(1));
    qsizetype length = 0;
    if (function == modbusrtu::ReadHoldingRegisters || function == modbusrtu::WriteSingleRegister)
        length = 8;
    else if (function == modbusrtu::WriteMultipleRegisters && m_frameBytes.size() >= 7)
        length = 9 + quint8(m_frameBytes.at(6));
    if (length == 0 || m_frameBytes.size() < length || hasValidCrc16(m_frameBytes.left(length)))
        return {};
    m_frameBytes.clear();
    m_parser.discardPending();
    ++m_checksumErrors;
    modbusrtu::Request r;
    r.address = static_cast<quint8>(m_address);
    r.function = function;
    ++m_answered;
    return {exceptionReply(r)};
}

QList<QByteArray> SimServoModbusDrive::handleFrame(const QByteArray &adu, qint64 nowUs)
{
    const Decoded<modbusrtu::Request> decoded = modbusrtu::decodeRequest(adu);
    if (!decoded.ok()) {
        ++m_ignored;
        qCDebug(lcSim) << describe() << "ignores" << adu.toHex(' ') << decoded.error;
        return {};
    }
    const modbusrtu::Request &r = *decoded.value;
    const bool broadcast = r.address == modbusrtu::BroadcastAddress;
    if (!broadcast && r.address != m_address)
        return {};
    if (broadcast)
        ++m_broadcasts;

    QByteArray reply;
    using namespace modbusrtu;
    if (r.function == WriteSingleRegister) {
        reply = (r.start == servomodbus::EeLegacyRegister && legacyFirmware())
            ? handleEe(r, servomodbus::EeFormat::Legacy, broadcast, nowUs)
            : exceptionReply(r);
    } else if (r.function == WriteMultipleRegisters && r.start == servomodbus::EeNewRegister) {
        reply = (r.count == 1 && !legacyFirmware()) ? handleEe(r, servomodbus::EeFormat::New, broadcast, nowUs)
                                                    : exceptionReply(r);
    } else if (!servomodbus::validateRequest(r).isEmpty()) {
        reply = exceptionReply(r);
    } else if (r.function == ReadHoldingRegisters) {
        reply = handleRead(r);
    } else {
        reply = handleWrite(r, broadcast);
    }
    if (broadcast || reply.isEmpty())
        return {};
    ++m_answered;
    return {reply};
}

QByteArray SimServoModbusDrive::exceptionReply(const modbusrtu::Request &request)
{
    ++m_exceptions;
    const quint8 addr = m_config.exceptionAddressFixed ? 0x01 : static_cast<quint8>(m_address);
    return modbusrtu::encodeExceptionReply(addr, request.function, modbusrtu::ServerDeviceFailure);
}

QByteArray SimServoModbusDrive::handleRead(const modbusrtu::Request &request)
{
    QList<quint16> values;
    values.reserve(request.count);
    for (int i = 0; i < request.count; ++i) {
        const quint16 reg = static_cast<quint16>(request.start + i);
        const int n = servomodbus::parameterIndex(reg);
        values.append(n >= 0 ? m_params[size_t(n)] : monitorRegister(reg));
    }
    return modbusrtu::encodeReadHoldingReply(static_cast<quint8>(m_address), values);
}

QByteArray SimServoModbusDrive::handleWrite(const modbusrtu::Request &request, bool broadcast)
{
    for (int i = 0; i < request.count; ++i) {
        const int n = servomodbus::parameterIndex(static_cast<quint16>(request.start + i));
        if (n >= 0 && n != servomodbus::FirmwareParameter)
            m_params[size_t(n)] = request.values.at(i);
    }
    if (broadcast)
        return {};
    return modbusrtu::encodeWriteMultipleReply(static_cast<quint8>(m_address), request.start, request.count);
}

QByteArray SimServoModbusDrive::handleEe(const modbusrtu::Request &request, servomodbus::EeFormat format,
                                         bool broadcast, qint64 nowUs)
{
    const quint16 code = request.values.value(0);
    const auto op = servomodbus::eeOpFromCode(code);
    if (!op)
        return exceptionReply(request);
    const quint8 addr = static_cast<quint8>(m_address);
    if (format == servomodbus::EeFormat::New) {
        applyEe(*op);
        return modbusrtu::encodeWriteMultipleReply(addr, servomodbus::EeNewRegister, 1);
    }
    if (m_ee && *m_ee == *op) {
        if (m_eeFinished) {
            m_ee.reset();
            m_eeFinished = false;
            return modbusrtu::encodeWriteSingleReply(addr, servomodbus::EeLegacyRegister, code);
        }
        return modbusrtu::encodeWriteSingleReply(addr, servomodbus::EeLegacyRegister, 0);
    }
    if (m_ee && !m_eeFinished) // busy with another operation
        return modbusrtu::encodeWriteSingleReply(addr, servomodbus::EeLegacyRegister, 0);
    startEe(*op, nowUs);
    if (m_eeFinished && !broadcast) { // instantaneous (eeBusyUs == 0)
        m_ee.reset();
        m_eeFinished = false;
        return modbusrtu::encodeWriteSingleReply(addr, servomodbus::EeLegacyRegister, code);
    }
    return modbusrtu::encodeWriteSingleReply(addr, servomodbus::EeLegacyRegister, 0);
}

void SimServoModbusDrive::startEe(servomodbus::EeOp op, qint64 nowUs)
{
    m_ee = op;
    m_eeFinished = false;
    m_eeDoneAtUs = nowUs + m_config.eeBusyUs;
    if (m_config.eeBusyUs == 0) {
        applyEe(op);
        m_eeFinished = true;
    }
}

void SimServoModbusDrive::applyEe(servomodbus::EeOp op)
{
    using servomodbus::EeOp;
    const quint16 firmware = m_params[servomodbus::FirmwareParameter];
    switch (op) {
    case EeOp::Set: m_eeprom = m_params; break;
    case EeOp::Read: m_params = m_eeprom; break;
    case EeOp::Backup: m_backup = m_params; break;
    case EeOp::Restore: m_params = m_backup; break;
    case EeOp::Defaults:
        m_params = factoryDefaults(m_config);
        m_eeprom = m_params;
        break;
    }
    m_params[servomodbus::FirmwareParameter] = firmware;
    m_eeprom[servomodbus::FirmwareParameter] = firmware;
    ++m_eeCompleted;
    m_lastEe = op;
    qCDebug(lcSim) << describe() << "EE operation" << servomodbus::eeOpMnemonic(op) << "done";
}

quint16 SimServoModbusDrive::parameter(int n) const
{
    return servomodbus::isParameterIndex(n) ? m_params[size_t(n)] : 0;
}

void SimServoModbusDrive::setParameter(int n, quint16 value)
{
    if (servomodbus::isParameterIndex(n))
        m_params[size_t(n)] = value;
}

quint16 SimServoModbusDrive::eepromParameter(int n) const
{
    return servomodbus::isParameterIndex(n) ? m_eeprom[size_t(n)] : 0;
}

quint16 SimServoModbusDrive::backupParameter(int n) const
{
    return servomodbus::isParameterIndex(n) ? m_backup[size_t(n)] : 0;
}

quint16 SimServoModbusDrive::monitorRegister(int reg) const
{
    const MotorModel &m = m_motor;
    const auto rule = m_config.positionRule;
    auto part = [rule](qint64 v, bool high) -> quint16 {
        auto p = servomodbus::splitPosition(v, rule);
        if (!p)
            p = servomodbus::splitPosition(v, servomodbus::PositionPairRule::BinaryWords);
        return p ? (high ? p->high : p->low) : 0;
    };
    const double countsPerRev = m.config().countsPerRev;
    const double turn = std::fmod(m.positionExact(), countsPerRev);
    const double rotor = turn < 0 ? turn + countsPerRev : turn;
    const double electrical = 2.0 * Pi * PolePairs * rotor / countsPerRev;
    const double amps = std::abs(m.current());
    switch (reg) {
    case 0x00: return s16(m.speedRpm());
    case 0x01: return part(m.position(), false);
    case 0x02: return part(m.position(), true);
    case 0x03: return part(m.commandPosition(), false);
    case 0x04: return part(m.commandPosition(), true);
    case 0x05: return part(m.positionError(), false);
    case 0x06: return part(m.positionError(), true);
    case 0x07: return s16(m.torquePercent());
    case 0x08: return s16(amps * 100.0);
    case 0x0A: return m_params[4];
    case 0x0B: return s16(std::abs(m.speed()) / 1000.0);
    case 0x0C: return s16(m.targetSpeed() * 60.0 / countsPerRev);
    case 0x0D: return s16(m.torquePercent());
    case 0x0E: return static_cast<quint16>(std::min(rotor, 65535.0));
    case 0x0F: return m.isEnabled() ? 0x0001 : 0x0000;
    case 0x10: return quint16((m.isEnabled() && m.alarmCode() == 0 ? 0x01 : 0x00) | (m.alarmCode() != 0 ? 0x02 : 0x00));
    case 0x11: {
        static const quint16 uvw[6] = {1, 3, 2, 6, 4, 5};
        const int sector = int(std::fmod(electrical, 2.0 * Pi) / (Pi / 3.0)) % 6;
        return uvw[sector];
    }
    case 0x13: return static_cast<quint16>(m.alarmCode());
    case 0x15: return s16(m.current() * std::cos(electrical) * 100.0);
    case 0x16: return s16(m.current() * std::cos(electrical + 2.0 * Pi / 3.0) * 100.0);
    default: return 0;
    }
}

void SimServoModbusDrive::setAlarm(int code)
{
    if (code != 0)
        m_motor.injectAlarm(code);
    else
        m_motor.clearAlarm();
}

void SimServoModbusDrive::powerCycle()
{
    const quint16 firmware = m_params[servomodbus::FirmwareParameter];
    m_params = m_eeprom;
    m_params[servomodbus::FirmwareParameter] = firmware;
    const int addr = m_params[servomodbus::AddressParameter];
    if (addr >= 1 && addr <= 247)
        m_address = addr;
    m_ee.reset();
    m_eeFinished = false;
    m_parser.reset();
    m_lastBytesUs = -1;
}

QJsonObject SimServoModbusDrive::saveState() const
{
    QJsonObject o;
    o.insert(QStringLiteral("family"), QStringLiteral("servo-modbus"));
    o.insert(QStringLiteral("address"), m_address);
    o.insert(QStringLiteral("baud"), m_baud);
    o.insert(QStringLiteral("firmware"), int(m_params[servomodbus::FirmwareParameter]));
    o.insert(QStringLiteral("alarm"), m_motor.alarmCode());
    o.insert(QStringLiteral("parameters"), toJson(m_params));
    o.insert(QStringLiteral("eeprom"), toJson(m_eeprom));
    o.insert(QStringLiteral("backup"), toJson(m_backup));
    return o;
}

bool SimServoModbusDrive::loadState(const QJsonObject &state, QString *error)
{
    if (state.value(QStringLiteral("family")).toString() != QLatin1String("servo-modbus")) {
        if (error)
            *error = QStringLiteral("state: not a servo-modbus drive");
        return false;
    }
    ParameterArray params{}, eeprom{}, backup{};
    if (!fromJson(state.value(QStringLiteral("parameters")), &params, "parameters", error)
        || !fromJson(state.value(QStringLiteral("eeprom")), &eeprom, "eeprom", error)
        || !fromJson(state.value(QStringLiteral("backup")), &backup, "backup", error))
        return false;
    const int address = state.value(QStringLiteral("address")).toInt(eeprom[servomodbus::AddressParameter]);
    if (address < 1 || address > 247) {
        if (error)
            *error = QStringLiteral("state: address %1 is not 1..247").arg(address);
        return false;
    }
    m_params = params;
    m_eeprom = eeprom;
    m_backup = backup;
    m_address = address;
    m_baud = state.value(QStringLiteral("baud")).toInt(m_baud);
    setAlarm(state.value(QStringLiteral("alarm")).toInt(0));
    m_ee.reset();
    m_eeFinished = false;
    m_parser.reset();
    m_lastBytesUs = -1;
    return true;
}

std::unique_ptr<SimSerialDevice> SimServoModbusDrive::create(const SimDeviceSpec &spec, Error *)
{
    Config c;
    c.address = spec.address;
    c.baud = spec.baud;
    c.demoMotion = spec.demoMotion;
    c.resonanceHz = spec.resonanceHz;
    return std::make_unique<SimServoModbusDrive>(c);
}

} // namespace dd
