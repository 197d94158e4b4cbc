#include "protocol/framedescriber.h"

#include "protocol/servocan.h"
#include "protocol/servomodbus.h"

#include <QStringList>

namespace dd {

namespace {

constexpr int kMaxListedValues = 4;   // a 20-register reply lists the first four

QString failed(const QString &reason)
{
    return reason.isEmpty() ? FrameDescriber::unknown()
                            : QStringLiteral("%1 (%2)").arg(FrameDescriber::unknown(), reason);
}

QString hex16(quint16 v)
{
    return QStringLiteral("0x") + QStringLiteral("%1").arg(v, 4, 16, QLatin1Char('0')).toUpper();
}

QString station(int address)
{
    return QStringLiteral("#%1 ").arg(address);
}

// The servo-modbus name of a register: a DP mnemonic, "PA<n>", or its number.
QString registerName(quint16 reg)
{
    if (const servomodbus::MonitorRegister *m = servomodbus::monitorRegister(reg))
        return QString::fromLatin1(m->mnemonic);
    const int pa = servomodbus::parameterIndex(reg);
    if (pa >= 0)
        return QStringLiteral("PA%1").arg(pa);
    return hex16(reg);
}

QString registerSpan(quint16 start, int count)
{
    if (count <= 1)
        return registerName(start);
    return QStringLiteral("%1–%2").arg(registerName(start), registerName(quint16(start + count - 1)));
}

QString eeName(quint16 code)
{
    if (const auto op = servomodbus::eeOpFromCode(code))
        return QString::fromLatin1(servomodbus::eeOpMnemonic(*op));
    return QString::number(code);
}

} // namespace

FrameDescriber::FrameDescriber(Family family, const QString &framing, const QVariantMap &options)
    : m_family(family)
{
    const QString f = framing.trimmed().toLower();
    if (f == QLatin1String("ascii"))
        m_serialFraming = SerialFraming::Ascii;
    else if (f == QLatin1String("plc"))
        m_serialFraming = SerialFraming::Plc;
    m_bigEndian = options.value(QStringLiteral("shuoke.byteOrder")).toString().trimmed().toLower()
                  == QLatin1String("big");
    m_twosComplement = options.value(QStringLiteral("shuoke.checksum")).toString().trimmed().toLower()
                       == QLatin1String("twos-complement");
    m_plcBase = quint16(options.value(QStringLiteral("shuoke.plcBase"), 0).toUInt());
}

QString FrameDescriber::unknown()
{
    return QStringLiteral("?");
}

void FrameDescriber::reset()
{
    m_modbusRequest.reset();
    m_shuokeRequest.reset();
}

QString FrameDescriber::describeSerial(Origin origin, const QByteArray &bytes)
{
    switch (m_family) {
    case Family::ServoModbus:
        return origin == Origin::Host ? describeModbusRequest(bytes) : describeModbusReply(bytes);
    case Family::Shuoke:
        return describeShuokeSerial(origin, bytes);
    case Family::ServoCan:
        break;
    }
    return unknown();
}

QString FrameDescriber::describeCan(Origin origin, const CanFrameData &frame)
{
    switch (m_family) {
    case Family::ServoCan:
        return describeServoCan(origin, frame);
    case Family::Shuoke:
        return describeShuokeCan(origin, frame);
    case Family::ServoModbus:
        break;
    }
    return unknown();
}

// ---- servo-can --------------------------------------------------------------------------

QString FrameDescriber::describeServoCan(Origin origin, const CanFrameData &frame) const
{
    using namespace servocan;
    const Decoded<Message> d = decode(frame);
    if (!d.ok())
        return failed(d.error);
    const Message &m = *d.value;
    QString text;
    switch (m.command) {
    case Command::Alarm:
        text = m.alarmCode() ? tr("alarm %1").arg(m.alarmCode()) : tr("no alarm");
        break;
    case Command::KeepAlive:
        text = tr("keep-alive");
        break;
    case Command::Heartbeat:
        text = m.heartbeatIdle() ? tr("heartbeat: idle, position %1").arg(m.value)
                                 : tr("heartbeat: running, position %1").arg(m.value);
        break;
    case Command::Read: {
        const ReadType type = m.readType().value_or(ReadType::Parameter);
        if (type == ReadType::Parameter) {
            text = origin == Origin::Host ? tr("read P%1").arg(m.paramIndex)
                                          : tr("P%1 = %2").arg(m.paramIndex).arg(m.paramValue);
            break;
        }
        const ReadTypeInfo info = readTypeInfo(type);
        const QString name = QCoreApplication::translate("dd::servocan", info.name);
        if (origin == Origin::Host) {
            text = tr("read %1").arg(name);
            break;
        }
        QString value;
        if (info.bitField)
            value = QStringLiteral("0x") + QString::number(quint32(m.value), 16).toUpper();
        else
            value = QString::number(scaledValue(type, m.value), 'f', info.decimals);
        if (info.unit && *info.unit)
            value += QLatin1Char(' ') + QCoreApplication::translate("dd::servocan", info.unit);
        text = tr("%1 = %2").arg(name, value);
        break;
    }
    case Command::Write:
        text = tr("write P%1 = %2").arg(m.paramIndex).arg(m.paramValue);
        break;
    case Command::RunSpeed:
        text = m.value ? tr("run at %1 r/min").arg(m.value) : tr("run at 0 r/min (halt)");
        break;
    case Command::MoveRelative:
        text = tr("move by %1").arg(m.value);
        break;
    case Command::MoveAbsolute:
        text = tr("move to %1").arg(m.value);
        break;
    case Command::PositioningSpeed:
        text = tr("positioning speed %1 r/min").arg(m.value);
        break;
    case Command::Enable:
        text = m.enableOn() ? tr("servo on") : tr("servo off");
        break;
    case Command::Stop:
        text = tr("stop");
        break;
    case Command::StopAndDisable:
        text = tr("stop and disable");
        break;
    case Command::SetPosition:
        text = tr("set position to %1").arg(m.value);
        break;
    case Command::ClearAlarm:
        text = tr("clear alarm");
        break;
    }
    return station(m.station) + text;
}

// ---- servo-modbus (Modbus RTU) ----------------------------------------------------------

QString FrameDescriber::describeModbusRequest(const QByteArray &bytes)
{
    using namespace modbusrtu;
    const Decoded<Request> d = decodeRequest(bytes);
    if (!d.ok()) {
        m_modbusRequest.reset();
        return failed(d.error);
    }
    const Request &r = *d.value;
    m_modbusRequest = r;
    QString text;
    switch (r.function) {
    case ReadHoldingRegisters:
        text = tr("read %1").arg(registerSpan(r.start, r.count));
        break;
    case WriteSingleRegister:
        if (r.start == servomodbus::EeLegacyRegister)
            text = tr("EE operation %1").arg(eeName(r.values.value(0)));
        else
            text = tr("write %1 = %2").arg(registerName(r.start)).arg(qint16(r.values.value(0)));
        break;
    case WriteMultipleRegisters:
        if (r.start == servomodbus::EeNewRegister && r.count == 1) {
            text = tr("EE operation %1").arg(eeName(r.values.value(0)));
        } else {
            QStringList values;
            for (int i = 0; i < r.values.size() && i < kMaxListedValues; ++i)
                values << QString::number(qint16(r.values.at(i)));
            if (r.values.size() > kMaxListedValues)
                values << QStringLiteral("…");
            text = tr("write %1 = %2").arg(registerSpan(r.start, r.count), values.join(QStringLiteral(", ")));
        }
        break;
    default:
        return failed({});
    }
    if (r.address == BroadcastAddress)
        return tr("all (broadcast): %1").arg(text);
    return station(r.address) + text;
}

QString FrameDescriber::describeModbusReply(const QByteArray &bytes) const
{
    using namespace modbusrtu;
    if (!m_modbusRequest)
        return failed(QStringLiteral("reply without a request"));
    const Request &req = *m_modbusRequest;
    const Decoded<Reply> d = decodeReply(bytes, req);
    if (!d.ok())
        return failed(d.error);
    const Reply &r = *d.value;
    if (r.isException)
        return station(r.address)
               + tr("exception %1: %2").arg(r.exceptionCode).arg(exceptionCodeName(r.exceptionCode));
    QString text;
    switch (r.function) {
    case ReadHoldingRegisters: {
        QStringList values;
        for (int i = 0; i < r.values.size() && i < kMaxListedValues; ++i)
            values << QStringLiteral("%1 = %2").arg(registerName(quint16(req.start + i))).arg(qint16(r.values.at(i)));
        if (r.values.size() > kMaxListedValues)
            values << tr("… (%1 values)").arg(r.values.size());
        text = values.join(QStringLiteral(", "));
        break;
    }
    case WriteSingleRegister:
        if (r.start == servomodbus::EeLegacyRegister) {
            const quint16 v = r.values.value(0);
            text = v == 0 ? tr("EE operation running") : tr("EE operation %1 done").arg(eeName(v));
        } else {
            text = tr("written %1 = %2").arg(registerName(r.start)).arg(qint16(r.values.value(0)));
        }
        break;
    case WriteMultipleRegisters:
        if (r.start == servomodbus::EeNewRegister && r.count == 1)
            text = tr("EE operation accepted");
        else
            text = tr("written %1").arg(registerSpan(r.start, r.count));
        break;
    default:
        return failed({});
    }
    return station(r.address) + text;
}

} // namespace dd
