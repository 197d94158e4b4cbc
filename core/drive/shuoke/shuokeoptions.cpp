#include "core/drive/shuoke/shuokeoptions.h"

#include "core/link/connectionsettings.h"

#include <QCoreApplication>

namespace dd {

QString shuokeFramingId(ShuokeFraming framing)
{
    switch (framing) {
    case ShuokeFraming::Rtu: return QStringLiteral("rtu");
    case ShuokeFraming::Ascii: return QStringLiteral("ascii");
    case ShuokeFraming::Can: return QStringLiteral("can");
    case ShuokeFraming::Plc: return QStringLiteral("plc");
    }
    return QString();
}

std::optional<ShuokeFraming> shuokeFramingFromId(const QString &id)
{
    const QString s = id.trimmed().toLower();
    for (ShuokeFraming f : {ShuokeFraming::Rtu, ShuokeFraming::Ascii, ShuokeFraming::Can, ShuokeFraming::Plc})
        if (s == shuokeFramingId(f))
            return f;
    return std::nullopt;
}

namespace {

// `allowed`: the accepted values, comma-separated tokens (not translated).
Error badValue(const QString &key, const QString &value, const QString &allowed)
{
    return {ErrorCode::InvalidArgument,
            QCoreApplication::translate("dd::ShuokeOptions", "%1 = \"%2\" is not a valid setting; use %3.")
                .arg(key, value, allowed)};
}

} // namespace

ShuokeOptions ShuokeOptions::fromSettings(const ConnectionSettings &settings, Error *error)
{
    ShuokeOptions o;
    Error e;
    auto fail = [&](const Error &err) {
        if (!e.isError())
            e = err;
    };
    const QVariantMap &m = settings.options;
    auto text = [&m](const char *key, const char *fallback) {
        return m.value(QLatin1String(key), QLatin1String(fallback)).toString().trimmed();
    };

    if (settings.framing.isEmpty()) {
        o.framing = settings.isCan() ? ShuokeFraming::Can : ShuokeFraming::Rtu;
    } else if (const auto f = shuokeFramingFromId(settings.framing)) {
        o.framing = *f;
    } else {
        fail(badValue(QStringLiteral("framing"), settings.framing, QStringLiteral("rtu, ascii, can, plc")));
    }
    if (settings.isCan() != (o.framing == ShuokeFraming::Can) && !e.isError())
        fail({ErrorCode::InvalidArgument,
              settings.isCan() ? QCoreApplication::translate("dd::ShuokeOptions",
                                                             "The %1 framing needs a serial port, not a CAN interface.")
                                     .arg(shuokeFramingId(o.framing))
                               : QCoreApplication::translate(
                                   "dd::ShuokeOptions",
                                   "The can framing needs a CAN interface (plugin:interface), not a serial port.")});

    const QString checksum = text("shuoke.checksum", "sum").toLower();
    if (checksum == QLatin1String("sum"))
        o.checksum = shuoke::AsciiCheck::PlainSum;
    else if (checksum == QLatin1String("twos-complement") || checksum == QLatin1String("lrc"))
        o.checksum = shuoke::AsciiCheck::TwosComplement;
    else
        fail(badValue(QStringLiteral("shuoke.checksum"), checksum, QStringLiteral("sum, twos-complement")));

    const QString order = text("shuoke.byteOrder", "little").toLower();
    if (order == QLatin1String("little"))
        o.byteOrder = shuoke::ByteOrder::LittleEndian;
    else if (order == QLatin1String("big"))
        o.byteOrder = shuoke::ByteOrder::BigEndian;
    else
        fail(badValue(QStringLiteral("shuoke.byteOrder"), order, QStringLiteral("little, big")));

    const QString broadcast = text("shuoke.broadcast", "0");
    if (broadcast == QLatin1String("0"))
        o.broadcast = shuoke::kBroadcastZero;
    else if (broadcast == QLatin1String("255"))
        o.broadcast = shuoke::kBroadcastAllOnes;
    else
        fail(badValue(QStringLiteral("shuoke.broadcast"), broadcast, QStringLiteral("0, 255")));

    const QString model = text("shuoke.model", "auto");
    if (model.compare(QLatin1String("auto"), Qt::CaseInsensitive) == 0) {
        o.model.reset();
    } else {
        bool known = false;
        for (shuoke::Model mdl : {shuoke::Model::M6505, shuoke::Model::M4505, shuoke::Model::M4505S}) {
            if (model.compare(shuoke::modelName(mdl), Qt::CaseInsensitive) == 0) {
                o.model = mdl;
                known = true;
            }
        }
        if (!known)
            fail(badValue(QStringLiteral("shuoke.model"), model, QStringLiteral("auto, M6505, M4505, M4505S")));
    }

    bool ok = true;
    const int gap = text("shuoke.minGapMs", "50").toInt(&ok);
    if (!ok || gap < 0 || gap > 10000)
        fail(badValue(QStringLiteral("shuoke.minGapMs"), text("shuoke.minGapMs", "50"),
                      QStringLiteral("0..10000 (ms)")));
    else
        o.minGapMs = gap;

    const QString gapFrom = text("shuoke.gapFrom", "command").toLower();
    if (gapFrom == QLatin1String("command") || gapFrom == QLatin1String("reply"))
        o.gapFromReply = gapFrom == QLatin1String("reply");
    else
        fail(badValue(QStringLiteral("shuoke.gapFrom"), gapFrom, QStringLiteral("command or reply")));

    const QString baseText = text("shuoke.plcBase", "0");
    const uint base = baseText.toUInt(&ok, 0);
    if (!ok || base > 0xFF00)
        fail(badValue(QStringLiteral("shuoke.plcBase"), baseText, QStringLiteral("0..65280")));
    else
        o.plcBase = static_cast<quint16>(base);

    const QString frame = text("shuoke.canFrame", "standard").toLower();
    if (frame == QLatin1String("standard") || frame == QLatin1String("extended"))
        o.can.extended = frame == QLatin1String("extended");
    else
        fail(badValue(QStringLiteral("shuoke.canFrame"), frame, QStringLiteral("standard, extended")));
    const QString extId = text("shuoke.canExtendedId", "address").toLower();
    if (extId == QLatin1String("address"))
        o.can.extendedId = shuoke::CanExtendedId::Address;
    else if (extId == QLatin1String("zero") || extId == QLatin1String("0"))
        o.can.extendedId = shuoke::CanExtendedId::Zero;
    else
        fail(badValue(QStringLiteral("shuoke.canExtendedId"), extId, QStringLiteral("address, zero")));

    o.scanSkipSilent = m.value(QStringLiteral("shuoke.scanSkipSilent"), true).toBool();

    if (error)
        *error = e;
    return o;
}

void ShuokeOptions::applyGap(qint32 baud, int bitsPerChar, int *minGapMs, int *minCommandSpacingMs) const
{
    if (gapFromReply) {
        *minGapMs = this->minGapMs;
        *minCommandSpacingMs = 0;
        return;
    }
    // 3.5 characters of silence end a frame (RTU); whole milliseconds, at least 1.
    const qint64 t35Us = baud > 0 ? (qint64(35) * bitsPerChar * 1000000 / 10 + baud - 1) / baud : 0;
    *minGapMs = std::max(1, int((t35Us + 999) / 1000));
    *minCommandSpacingMs = this->minGapMs;
}

} // namespace dd
