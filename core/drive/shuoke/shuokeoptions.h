#pragma once

#include "core/common/error.h"
#include "core/protocol/shuoke/shuokeascii.h"
#include "core/protocol/shuoke/shuokecan.h"
#include "core/protocol/shuoke/shuokecommands.h"
#include "core/protocol/shuoke/shuokevalues.h"

#include <QString>
#include <QVariantMap>
#include <optional>

namespace dd {

struct ConnectionSettings;

// The four framings of the Shuoke command set (docs/protocols/shuoke.md).
enum class ShuokeFraming { Rtu, Ascii, Can, Plc };
QString shuokeFramingId(ShuokeFraming framing); // "rtu", "ascii", "can", "plc"
std::optional<ShuokeFraming> shuokeFramingFromId(const QString &id);

// The settings of a Shuoke link where the seed is silent or ambiguous
// (docs/protocols/shuoke.md), read from ConnectionSettings::framing and ::options:
//   framing                 rtu (serial default) | ascii | can (CAN default) | plc
//   "shuoke.checksum"       sum (default) | twos-complement     ASCII check byte
//   "shuoke.byteOrder"      little (default) | big              32-bit data
//   "shuoke.broadcast"      0 (default) | 255
//   "shuoke.model"          auto (default) | M6505 | M4505 | M4505S
//   "shuoke.minGapMs"       50 (default)                        time between commands
//   "shuoke.gapFrom"        command (default) | reply           what minGapMs counts from:
//                           the previous command, as the drive counts (and at least 3.5
//                           characters of quiet after each reply), or the previous reply
//   "shuoke.plcBase"        0 (default)                         PLC mapping base (0x3F)
//   "shuoke.canFrame"       standard (default) | extended       CAN identifiers (drive 0x4A)
//   "shuoke.canExtendedId"  address (default) | zero            extended identifier value
//   "shuoke.scanSkipSilent" true (default) | false              discovery: see ShuokeDiscovery
struct ShuokeOptions
{
    ShuokeFraming framing = ShuokeFraming::Rtu;
    shuoke::AsciiCheck checksum = shuoke::AsciiCheck::PlainSum;
    shuoke::ByteOrder byteOrder = shuoke::ByteOrder::LittleEndian;
    quint8 broadcast = shuoke::kBroadcastZero;
    std::optional<shuoke::Model> model; // nullopt: detected by ShuokeDrive::refreshIdentity()
    int minGapMs = 50;
    bool gapFromReply = false;
    quint16 plcBase = 0;
    shuoke::CanOptions can;
    bool scanSkipSilent = true;

    // Pacing of a serial link at `baud` (minGapMs / minCommandSpacingMs of SerialSettings).
    void applyGap(qint32 baud, int bitsPerChar, int *minGapMs, int *minCommandSpacingMs) const;

    // The options of `settings`; an unknown value is an InvalidArgument error naming the key.
    static ShuokeOptions fromSettings(const ConnectionSettings &settings, Error *error = nullptr);
};

} // namespace dd
