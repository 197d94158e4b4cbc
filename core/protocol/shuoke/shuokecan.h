#pragma once

#include "core/protocol/canframedata.h"
#include "core/protocol/codecresult.h"
#include "core/protocol/shuoke/shuokeframe.h"

// Shuoke over CAN: identifier = device address (1..250, 0 = broadcast), data = the RTU
// frame without its CRC ([addr][cmd][len][data]) zero-padded to 8 bytes, DLC 8.
// A frame with more than 5 data bytes (0x40 with 7) cannot go over CAN.
//
// Extended frames (drive setting 0x4A): the seed says once "extended ID fixed 0", once
// "extended ID = address". Decision: extended ID = address by default, 0 as a setting.
// On receive both are accepted.
namespace dd::shuoke {

enum class CanExtendedId : quint8 { Address, Zero };

struct CanOptions
{
    bool extended = false;
    CanExtendedId extendedId = CanExtendedId::Address;
};

constexpr int kCanFrameBytes = 8;
constexpr int kCanMaxData = kCanFrameBytes - 3;

Decoded<CanFrameData> encodeCan(const Frame &frame, const CanOptions &options = {});

// Checks: 3..8 data bytes holding [addr][cmd][len][data] (a DLC below 8 is tolerated when
// it still holds len data bytes; padding is not checked); a standard identifier equals the
// address byte; an extended identifier equals the address byte or 0.
Decoded<Frame> decodeCan(const CanFrameData &can);

} // namespace dd::shuoke
