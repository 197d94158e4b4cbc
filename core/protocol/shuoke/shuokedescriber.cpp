#include "core/protocol/shuoke/shuokedescriber.h"

#include "core/protocol/modbus/modbusrtu.h"
#include "core/protocol/shuoke/shuokeascii.h"
#include "core/protocol/shuoke/shuokecan.h"
#include "core/protocol/shuoke/shuokecommands.h"
#include "core/protocol/shuoke/shuokeplc.h"
#include "core/protocol/shuoke/shuokertu.h"
#include "core/protocol/shuoke/shuokevalues.h"

#include <QStringList>

namespace dd {

namespace {

QString shuokeCommandName(quint8 code)
{
    if (const shuoke::CommandInfo *info = shuoke::commandInfo(code))
        return QCoreApplication::translate("dd::shuoke", info->name);
    return shuoke::commandName(code);
}

} // namespace

ShuokeDescriber::ShuokeDescriber(const QString &framing, const QVariantMap &options)
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

QString ShuokeDescriber::describeSerial(Origin origin, const QByteArray &bytes)
{
    using namespace shuoke;
    if (m_serialFraming == SerialFraming::Plc) {
        PlcOptions options;
        options.base = m_plcBase;
        if (origin == Origin::Host) {
            const Decoded<Frame> d = decodePlcRequest(bytes, options);
            if (!d.ok()) {
                m_request.reset();
                return failed(d.error);
            }
            return describeFrame(origin, *d.value);
        }
        if (!m_request)
            return failed(QStringLiteral("reply without a request"));
        const Decoded<Frame> d = decodePlcReply(bytes, *m_request, options);
        return d.ok() ? describeFrame(origin, *d.value) : failed(d.error);
    }
    Decoded<Frame> d;
    if (m_serialFraming == SerialFraming::Ascii) {
        AsciiOptions options;
        options.check = m_twosComplement ? AsciiCheck::TwosComplement : AsciiCheck::PlainSum;
        d = decodeAscii(bytes, options);
    } else {
        d = decodeRtu(bytes);
    }
    if (!d.ok()) {
        if (origin == Origin::Host)
            m_request.reset();
        return failed(d.error);
    }
    return describeFrame(origin, *d.value);
}

QString ShuokeDescriber::describeCan(Origin origin, const CanFrameData &frame)
{
    const Decoded<shuoke::Frame> d = shuoke::decodeCan(frame);
    if (!d.ok()) {
        if (origin == Origin::Host)
            m_request.reset();
        return failed(d.error);
    }
    return describeFrame(origin, *d.value);
}

QString ShuokeDescriber::describeFrame(Origin origin, const shuoke::Frame &frame)
{
    using namespace shuoke;
    const QString who = QStringLiteral("#%1 ").arg(frame.address);
    if (origin == Origin::Host) {
        m_request = frame;
        const QString value = valueText(frame.command, frame.data, true);
        const QString name = shuokeCommandName(frame.command);
        const QString text = value.isEmpty() ? name : name + QLatin1Char(' ') + value;
        return isBroadcastAddress(frame.address) ? tr("all (broadcast): %1").arg(text) : who + text;
    }
    // A reply is named after the request it answers (0x42..0x46 answer with 0x41).
    quint8 command = frame.command;
    if (m_request && isReplyTo(frame, *m_request))
        command = m_request->command;
    const QString name = shuokeCommandName(command);
    if (frame.failure) {
        QString why;
        if (m_serialFraming == SerialFraming::Plc)
            why = modbusrtu::exceptionCodeName(frame.failureCode);
        else if (const char *text = failureCodeText(frame.failureCode))
            why = QCoreApplication::translate("dd::shuoke", text);
        else
            why = failureDescription(frame.failureCode);
        return who + tr("%1 failed: %2").arg(name, why);
    }
    const QString value = valueText(command, frame.data, false);
    return who + (value.isEmpty() ? tr("%1: OK").arg(name) : tr("%1 → %2").arg(name, value));
}

QString ShuokeDescriber::valueText(quint8 command, const QByteArray &data, bool request) const
{
    using namespace shuoke;
    if (data.isEmpty())
        return {};
    const ByteOrder order = m_bigEndian ? ByteOrder::BigEndian : ByteOrder::LittleEndian;
    if (!request && command == CmdQueryStatus) {
        if (const auto s = decodeMotionStatus(data)) {
            QStringList flags{s->running ? tr("running") : tr("idle")};
            if (s->leftLimit)
                flags << tr("left limit");
            if (s->origin)
                flags << tr("origin");
            if (s->rightLimit)
                flags << tr("right limit");
            if (s->enableInput)
                flags << tr("enable input");
            return flags.join(QStringLiteral(", "));
        }
    }
    if (!request && (command == CmdReadInputs || command == CmdReadOtherInputs)) {
        if (const auto bits = decodeInputBits(data))
            return tr("inputs %1").arg(uint(*bits), 5, 2, QLatin1Char('0'));
    }
    if (data.size() == 4) {
        if (command == CmdMoveRelativeDirection24 || command == CmdRunSpeedDirection24
            || command == CmdHomeOrSCurveDirection24) {
            if (const auto v = decodeDirection24(data, order))
                return QString::number(*v);
        }
        if (const auto v = decodeInt32(data, order))
            return QString::number(*v);
    }
    if (data.size() == 2) {
        if (const auto v = decodeUInt16(data, order))
            return QString::number(*v);
    }
    if (data.size() == 1) {
        const int v = quint8(data.at(0));
        if (command == CmdHome || command == CmdHomeOrSCurveInt32 || command == CmdHomeOrSCurveDirection24)
            return v ? tr("positive first") : tr("negative first");
        if ((command == CmdGetBaudCode || command == CmdSetBaudCode) && baudRateForCode(v))
            return tr("code %1 (%2 baud)").arg(v).arg(baudRateForCode(v));
        if (command == CmdCanBitrate && canBitrateForCode(v))
            return tr("code %1 (%2 kbit/s)").arg(v).arg(canBitrateForCode(v) / 1000);
        return QString::number(v);
    }
    return QString::fromLatin1(data.toHex(' ').toUpper());
}

} // namespace dd
