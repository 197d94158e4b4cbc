#include "core/drive/shuoke/shuokeparameter.h"

namespace dd {

using namespace shuoke;

QByteArray ShuokeParameter::encode(qint64 value, ByteOrder order) const
{
    if (size == 1)
        return QByteArray(1, static_cast<char>(static_cast<quint8>(value)));
    return encodeUInt32(static_cast<quint32>(value), order);
}

std::optional<qint64> ShuokeParameter::decode(const QByteArray &data, ByteOrder order) const
{
    if (size == 1) {
        if (data.size() != 1)
            return std::nullopt;
        return static_cast<quint8>(data.at(0));
    }
    const auto v = decodeUInt32(data, order);
    if (!v)
        return std::nullopt;
    return static_cast<qint64>(*v);
}

const QList<ShuokeParameter> &ShuokeParameter::all()
{
    static const QList<ShuokeParameter> table = {
        // Readable set/get pairs.
        {CmdSetBaudCode, CmdGetBaudCode, 1, kMinBaudCode, kMaxBaudCode, "baud-code"},
        {CmdSetStartSpeed, CmdGetStartSpeed, 4, 0, kMaxSpeed, "start-speed"},
        {CmdSetMaxSpeed, CmdGetMaxSpeed, 4, 0, kMaxSpeed, "max-speed"},
        {CmdSetStopSpeed, CmdGetStopSpeed, 4, 0, kMaxSpeed, "stop-speed"},
        {CmdSetAcceleration, CmdGetAcceleration, 4, 0, kMaxSpeed, "acceleration"},
        {CmdSetDeceleration, CmdGetDeceleration, 4, 0, kMaxSpeed, "deceleration"},
        {CmdSetHomingSpeed, CmdGetHomingSpeed, 4, 0, kMaxSpeed, "homing-speed"},
        {CmdSetGearNumerator, CmdGetGearNumerator, 4, 1, 0xFFFF, "gear-numerator"},
        {CmdSetGearDenominator, CmdGetGearDenominator, 4, 1, 0xFFFF, "gear-denominator"},
        // Write-only settings.
        {CmdSkipCrcCheck, 0, 1, 0, 1, "skip-crc-check"},
        {CmdFixedLengthReplies, 0, 1, 0, 1, "fixed-length-replies"},
        {CmdCanFrameFormat, 0, 1, 0, 1, "can-frame-format"},
        {CmdCanBitrate, 0, 1, kMinCanBitrateCode, kMaxCanBitrateCode, "can-bitrate-code"},
        {CmdEncoderDirection, 0, 1, 0, 1, "encoder-direction"},
        {CmdMotionDirection, 0, 1, 0, 1, "motion-direction"},
        {CmdErrorCorrection, 0, 1, 0, 1, "error-correction"},
        {CmdEncoderAbTolerance, 0, 4, 0, 0x7FFFFFFF, "encoder-ab-tolerance"},
        {CmdNoEncoderMaxPulses, 0, 4, 0, 0x7FFFFFFF, "encoder-loss-limit"},
    };
    return table;
}

const ShuokeParameter *ShuokeParameter::byIndex(int index)
{
    for (const ShuokeParameter &p : all())
        if (p.setCommand == index)
            return &p;
    return nullptr;
}

} // namespace dd
