#include "core/protocol/servomodbus/servomodbusdescriber.h"

#include "core/protocol/servomodbus/servomodbus.h"

#include <QStringList>

namespace dd {

namespace {

constexpr int kMaxListedValues = 4; // a 20-register reply lists the first four

QString hex16(quint16 v)
{
    return QStringLiteral("0x") + QStringLiteral("%1").arg(v, 4, 16, QLatin1Char('0')).toUpper();
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

QString ServoModbusDescriber::describeSerial(Origin origin, const QByteArray &bytes)
{
    return origin == Origin::Host ? describeRequest(bytes) : describeReply(bytes);
}

QString ServoModbusDescriber::describeRequest(const QByteArray &bytes)
{
    using namespace modbusrtu;
    const Decoded<Request> d = decodeRequest(bytes);
    if (!d.ok()) {
        m_request.reset();
        return failed(d.error);
    }
    const Request &r = *d.value;
    m_request = r;
    QString text;
    switch (r.function) {
    case ReadHoldingRegisters: text = tr("read %1").arg(registerSpan(r.start, r.count)); break;
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
    default: return failed({});
    }
    if (r.address == BroadcastAddress)
        return tr("all (broadcast): %1").arg(text);
    return station(r.address) + text;
}

QString ServoModbusDescriber::describeReply(const QByteArray &bytes) const
{
    using namespace modbusrtu;
    if (!m_request)
        return failed(QStringLiteral("reply without a request"));
    const Request &req = *m_request;
    const Decoded<Reply> d = decodeReply(bytes, req);
    if (!d.ok())
        return failed(d.error);
    const Reply &r = *d.value;
    if (r.isException)
        return station(r.address) + tr("exception %1: %2").arg(r.exceptionCode).arg(exceptionCodeName(r.exceptionCode));
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
    default: return failed({});
    }
    return station(r.address) + text;
}

} // namespace dd
