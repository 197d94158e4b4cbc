#pragma once

#include <QByteArray>
#include <QtGlobal>

namespace dd::shuoke {

// One Shuoke command or reply, independent of the framing (RTU, ASCII, CAN, PLC).
//
// A failure reply is `[addr][cmd | 0x80][len = 1][code]` on the wire; here it is
// `failure = true`, `command` = the command without the 0x80 bit, `failureCode` = code,
// and `data` is ignored when encoding and empty after decoding.
// In PLC mode a failure is a Modbus exception reply, and `failureCode` is the Modbus
// exception code.
struct Frame
{
    quint8 address = 0;
    quint8 command = 0; // 0x20..0x66; never carries the 0x80 failure bit
    QByteArray data;    // the command's data bytes (0..7 for every known command)
    bool failure = false;
    quint8 failureCode = 0; // 0x01..0x05 (see failureCodeText); meaningful when failure

    static Frame make(quint8 address, quint8 command, const QByteArray &data = {})
    {
        Frame f;
        f.address = address;
        f.command = command;
        f.data = data;
        return f;
    }
    static Frame failureReply(quint8 address, quint8 command, quint8 code)
    {
        Frame f;
        f.address = address;
        f.command = static_cast<quint8>(command & 0x7F);
        f.failure = true;
        f.failureCode = code;
        return f;
    }

    // The command byte on the wire (with the 0x80 bit for a failure reply).
    quint8 commandByte() const { return failure ? static_cast<quint8>(command | 0x80) : command; }
    // The data bytes on the wire: the failure code for a failure reply, else `data`.
    QByteArray payload() const { return failure ? QByteArray(1, static_cast<char>(failureCode)) : data; }

    bool operator==(const Frame &o) const
    {
        if (address != o.address || command != o.command || failure != o.failure)
            return false;
        return failure ? failureCode == o.failureCode : data == o.data;
    }
    bool operator!=(const Frame &o) const { return !(*this == o); }
};

} // namespace dd::shuoke
