// FrameDescriber: the shuoke family (RTU, ASCII, PLC and CAN framings).
#include "protocol/framedescriber.h"

#include "protocol/shuokeascii.h"
#include "protocol/shuokecan.h"
#include "protocol/shuokecommands.h"
#include "protocol/shuokeplc.h"
#include "protocol/shuokertu.h"
#include "protocol/shuokevalues.h"

#include <QStringList>

namespace dd {

namespace {

QString failedShuoke(const QString &reason)
{
    return QStringLiteral("%1 (%2)").arg(FrameDescriber::unknown(), reason);
}

QString shuokeCommandName(quint8 code)
{
    if (const shuoke::CommandInfo *info = shuoke::commandInfo(code))
        return QCoreApplication::translate("dd::shuoke", info->name);
    return shuoke::commandName(code);
}

} // namespace

QString FrameDescriber::describeShuokeSerial(Origin origin, const QByteArray &bytes)
{
    using namespace shuoke;
    if (m_serialFraming == SerialFraming::Plc) {
        PlcOptions options;
        options.base = m_plcBase;
        if (origin == Origin::Host) {
            const Decoded<Frame> d = decodePlcRequest(bytes, options);
            if (!d.ok()) {
                m_shuokeRequest.reset();
                return failedShuoke(d.error);
            }
            return describeShuokeFrame(origin, *d.value);
        }
        if (!m_shuokeRequest)
            return failedShuoke(QStringLiteral("reply without a request"));
        const Decoded<Frame> d = decodePlcReply(bytes, *m_shuokeRequest, options);
        return d.ok() ? describeShuokeFrame(origin, *d.value) : failedShuoke(d.error);
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
            m_shuokeRequest.reset();
        return failedShuoke(d.error);
    }
    return describeShuokeFrame(origin, *d.value);
}

QString FrameDescriber::describeShuokeCan(Origin origin, const CanFrameData &frame)
{
    const Decoded<shuoke::Frame> d = shuoke::decodeCan(frame);
    if (!d.ok()) {
        if (origin == Origin::Host)
            m_shuokeRequest.reset();
        return failedShuoke(d.error);
    }
    return describeShuokeFrame(origin, *d.value);
}

QString FrameDescriber::describeShuokeFrame(Origin origin, const shuoke::Frame &frame)
{
    using namespace shuoke;
    const QString who = QStringLiteral("#%1 ").arg(frame.address);
    if (origin == Origin::Host) {
        m_shuokeRequest = frame;
        const QString value = shuokeValue(frame.command, frame.data, true);
        const QString name = shuokeCommandName(frame.command);
        const QString text = value.isEmpty() ? name : name + QLatin1Char(' ') + value;
        return isBroadcastAddress(frame.address) ? tr("all (broadcast): %1").arg(text) : who + text;
    }
    // A reply is named after the request it answers (0x42..0x46 answer with 0x41).
    quint8 command = frame.command;
    if (m_shuokeRequest && isReplyTo(frame, *m_shuokeRequest))
        command = m_shuokeRequest->command;
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
    const QString value = shuokeValue(command, frame.data, false);
    return who + (value.isEmpty() ? tr("%1: OK").arg(name) : tr("%1 → %2").arg(name, value));
}

QString FrameDescriber::shuokeValue(quint8 command, const QByteArray &data, bool request) const
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
