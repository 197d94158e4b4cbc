#pragma once

#include <QtGlobal>

namespace dd {

// How much bit stuffing a CAN frame time includes.
enum class CanStuffing {
    None,     // the frame's nominal bits only: the shortest the frame can ever take
    WorstCase // nominal bits + the most stuff bits the frame can need (one per 4 bits of the
              // stuffed region after the first): the longest the frame can take
};

// Wire-time arithmetic shared by the simulator (which paces replies with it), the host-side
// links (timeouts that cover the bytes' time) and the benchmarks (floors). All results are
// exact, in microseconds as double; round up (std::ceil) when scheduling so that nothing
// leaves early.
//
// Serial: an asynchronous character is start bit + data bits + parity + stop bits; the
// project's drives use 10 bits (8N1), the default everywhere. Bytes are assumed back to back
// (no idle gap between characters).
//
// CAN: a classical data frame (2.0A = 11-bit identifier, 2.0B = 29-bit identifier), counted
// from the start-of-frame bit up to and including the 3-bit intermission that must pass
// before the next frame may start (so that frame times add up to bus occupancy):
//   2.0A: SOF 1, ID 11, RTR 1, IDE 1, r0 1, DLC 4, data 8n, CRC 15   = 34 + 8n  (stuffed region)
//   2.0B: SOF 1, ID 11, SRR 1, IDE 1, ID 18, RTR 1, r1 r0 2, DLC 4,
//         data 8n, CRC 15                                               = 54 + 8n  (stuffed region)
//   both: CRC delimiter 1, ACK slot 1, ACK delimiter 1, EOF 7, intermission 3 = 13 (never stuffed)
// Worst-case stuffing adds floor((stuffedRegion - 1) / 4) bits.
//   DLC 8: 2.0A 111 bits nominal, 135 worst case; 2.0B 131 nominal, 160 worst case.
//
// Which is used where:
//   - SimCanBus paces every frame with CanStuffing::WorstCase.
//   - The benchmark floors use CanStuffing::WorstCase too (the "nominal stuffed estimate"),
//     so that a measurement against the simulator can be compared with its floor directly.
//   - CanStuffing::None is the absolute physical minimum; use it when a bound must never
//     exceed what real hardware could achieve.
class WireTime
{
public:
    WireTime() = delete;

    static constexpr int DefaultBitsPerChar = 10; // 1 start + 8 data + 1 stop
    static constexpr int CanIntermissionBits = 3;

    // Time of one character at `baud`, in µs. 0 when baud <= 0.
    static double serialCharUs(int baud, int bitsPerChar = DefaultBitsPerChar);
    // Time of `bytes` characters sent back to back at `baud`, in µs. 0 when baud <= 0.
    static double serialBytesUs(qsizetype bytes, int baud, int bitsPerChar = DefaultBitsPerChar);

    // Modbus RTU end-of-frame silence t3.5 = 3.5 character times; above 19200 baud the
    // Modbus spec fixes it at 1750 µs, so there the result is max(3.5 chars, 1750 µs).
    static double modbusSilenceUs(int baud, int bitsPerChar = DefaultBitsPerChar);
    // 3.5 character times at every baud: what DriveDesk keeps before a request to the drive
    // that has just answered (ModbusLink::sameDriveGapUs, docs/reliability.md).
    static double modbusSameDriveSilenceUs(int baud, int bitsPerChar = DefaultBitsPerChar);
    // Modbus RTU inter-character limit t1.5 = 1.5 character times; max(…, 750 µs) above 19200.
    static double modbusInterCharUs(int baud, int bitsPerChar = DefaultBitsPerChar);

    // Bits a classical CAN data frame with `dlc` data bytes (clamped to 0..8) occupies on the
    // bus, including the 3-bit intermission (see the table above).
    static int canFrameBits(int dlc, bool extended, CanStuffing stuffing = CanStuffing::WorstCase);
    // Time of that frame at `bitrate` bit/s, in µs. 0 when bitrate <= 0.
    static double canFrameUs(int dlc, bool extended, int bitrate, CanStuffing stuffing = CanStuffing::WorstCase);
};

} // namespace dd
