#pragma once

#include "core/common/family.h"

#include <QString>
#include <QVariantMap>

namespace dd {

// Everything needed to reach drives of one family on one link. The CLI's global options
// and the GUI's connect dialog both fill this.
struct ConnectionSettings
{
    Family family = Family::ServoModbus;
    QString port;       // serial device; empty when `can` is set
    QString can;        // "plugin:interface"; empty for serial
    int baud = 0;       // 0: the family default (FamilyTraits::defaultBaud)
    int bitrate = 0;    // 0: the family default (FamilyTraits::defaultBitrate)
    QString framing;    // shuoke: rtu | ascii | can | plc; empty: rtu (serial) / can (CAN)
    int timeoutMs = -1; // response allowance beyond wire time; -1: family default
    int retries = -1;   // -1: family default
    // Family settings where the protocol documents are ambiguous
    // (docs/protocols/, "Decision:"), e.g. "shuoke.checksum" = "sum" | "twos-complement",
    // "shuoke.byteOrder" = "little" | "big", "shuoke.broadcast" = 0 | 255,
    // "shuoke.plcBase" = N, "shuoke.minGapMs" = 50, "servo-modbus.positionRule" =
    // "binary" | "decimal10000" | "decimal100000", "servo-modbus.eeFormat" = "auto" |
    // "legacy" | "new".
    QVariantMap options;

    bool isCan() const { return !can.isEmpty(); }
    QString linkName() const { return isCan() ? can : port; }
};

} // namespace dd
