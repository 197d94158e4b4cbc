#pragma once

#include "core/protocol/codecresult.h"
#include "core/protocol/shuoke/shuokeframe.h"

#include <QByteArray>
#include <QList>

// Shuoke "PLC mode": the command set mapped onto Modbus RTU registers (RS485 only).
//
// - Register address = mapping base (set with 0x3F over RTU) + command code.
// - Write (function 0x10): 2 registers (4 bytes); 1 register (2 bytes) for 0x5C..0x5E.
//   The register bytes are the RTU command's data bytes in the same order, zero-padded
//   (seed: `02 00 00 00` sets address 2; 0x3E sends `dir 00 00 00`). Commands without
//   data (0x38, 0x3A, 0x3C, 0x3D; 0x59/0x5B "clear") write zeros.
// - Read (function 0x03): 2 registers; 0x3B reads 4 (first 5 bytes meaningful); the
//   handshake 0x20 and query address 0x21 read 0 registers (not standard Modbus, which
//   is why these ADUs are built here). The reply's first bytes are the RTU reply data
//   (0x23: `code 00 00 00`).
// - Only the commands the seed's PLC chapter lists are mapped (CommandInfo::plcAccess).
// - A write reply echoes register and count; it carries none of the RTU reply data.
// - A Modbus exception reply [addr][fc | 0x80][code] becomes a failure Frame whose
//   failureCode is the Modbus exception code.
namespace dd::shuoke {

enum PlcFunction : quint8 { PlcReadRegisters = 0x03, PlcWriteRegisters = 0x10 };

struct PlcOptions
{
    quint16 base = 0; // mapping base set with 0x3F
};

// What a Modbus client has to send for a request.
struct PlcRequestLayout
{
    quint8 function = 0; // PlcReadRegisters or PlcWriteRegisters
    quint16 registerAddress = 0;
    quint16 registerCount = 0;
    QByteArray values; // write: 2 x registerCount bytes; read: empty
};

Decoded<PlcRequestLayout> plcRequestLayout(const Frame &request, const PlcOptions &options = {});

// Host side: the complete request ADU (with CRC), the size of a success reply ADU
// (-1 when the command has no PLC mapping; an exception reply is 5 bytes), and the reply.
Decoded<QByteArray> encodePlcRequest(const Frame &request, const PlcOptions &options = {});
int plcReplySize(const Frame &request);
Decoded<Frame> decodePlcReply(const QByteArray &adu, const Frame &request, const PlcOptions &options = {});
// The RTU reply data of `command` inside the register bytes a Modbus client returned
// (the first bytes; 0x3B: 5 of 8). Fails when the bytes are too few.
Decoded<QByteArray> plcReplyData(quint8 command, const QByteArray &registerBytes);

// Drive side (simulator): the request a PLC ADU carries, and the reply ADU for it.
Decoded<Frame> decodePlcRequest(const QByteArray &adu, const PlcOptions &options = {});
Decoded<QByteArray> encodePlcReply(const Frame &reply, const Frame &request, const PlcOptions &options = {});

// Register words as Modbus carries them: high byte first.
QList<quint16> plcBytesToRegisters(const QByteArray &bytes); // an odd last byte is dropped
QByteArray plcRegistersToBytes(const QList<quint16> &registers);

} // namespace dd::shuoke
