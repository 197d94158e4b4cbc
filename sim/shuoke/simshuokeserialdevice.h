#pragma once

#include "core/protocol/shuoke/shuokeascii.h"
#include "sim/bench/simfamilies.h"
#include "sim/bus/simserialdevice.h"
#include "sim/shuoke/simshuokedrive.h"

#include <functional>

namespace dd {

// A simulated Shuoke drive on a serial bus (SimSerialBus), in one of the serial framings:
//   Rtu    [addr][cmd][len][data][crc lo][crc hi]
//   Ascii  ':' hex ... check CR LF, with the configured check byte (plain sum or LRC)
//   Plc    standard Modbus RTU (0x03 / 0x10 on base + command) - and, as a real drive in
//          PLC mode does, Shuoke RTU frames too (0x3F, which sets the base, is RTU only).
// Drive-side framing: a frame that stays incomplete is dropped after a silence; a frame
// addressed to this drive with a bad CRC / check byte is answered with failure 0x02 (the
// handshake 0x20 is taken without a CRC check; setting 0x48 = 1 skips the check for all);
// bad-CRC frames for others are skipped byte by byte (resynchronisation). With setting
// 0x49 = 1 RTU replies use the fixed 10-byte layout. A Modbus request for a register that
// maps to no command gets exception 0x02; a Shuoke failure in PLC mode is a Modbus
// exception with the failure code.
class SimShuokeSerialDevice : public SimSerialDevice
{
public:
    enum class Framing { Rtu, Ascii, Plc };

    explicit SimShuokeSerialDevice(const SimShuokeDrive::Config &config = {}, Framing framing = Framing::Rtu,
                                   shuoke::AsciiCheck check = shuoke::AsciiCheck::PlainSum);

    QList<QByteArray> onBusBytes(const QByteArray &bytes, qint64 nowUs) override;
    int baud() const override;
    QString describe() const override;
    void advanceTo(qint64 nowUs) override;

    // The bus clock (SimSerialBus::nowUs): with it the drive is brought up to date when it
    // is looked at (drive()) and baud() knows when the power-up window ends even before the
    // next chunk arrives. Without it the drive's time is that of the last chunk.
    void setClock(std::function<qint64()> nowUs) { m_clock = std::move(nowUs); }
    // The family's serial entry in the simulator table (sim/bench/simfamilies.h).
    static std::unique_ptr<SimSerialDevice> create(const SimDeviceSpec &spec, Error *error);
    // The drive, advanced to the bus clock when there is one.
    SimShuokeDrive &drive();
    const SimShuokeDrive &drive() const { return m_drive; }
    Framing framing() const { return m_framing; }
    void setFraming(Framing framing)
    {
        m_framing = framing;
        m_rx.clear();
    }
    shuoke::AsciiCheck asciiCheck() const { return m_check; }
    void setAsciiCheck(shuoke::AsciiCheck check) { m_check = check; }
    // Restart the drive now (pending address etc. apply; 9600 for the power-up window).
    void powerCycle();

    quint64 checksumErrors() const { return m_checksumErrors; }
    quint64 discardedBytes() const { return m_discarded; }

private:
    QList<QByteArray> frameBinary(qint64 nowUs);
    QList<QByteArray> frameAscii(qint64 nowUs);
    bool takeModbus(qint64 nowUs, QList<QByteArray> *out, bool *wait);
    QByteArray encodeRtuReply(const shuoke::Frame &reply) const;
    QByteArray encodeAsciiReply(const shuoke::Frame &reply) const;
    void drop(qsizetype n);

    qint64 clockUs() const;

    SimShuokeDrive m_drive;
    std::function<qint64()> m_clock;
    Framing m_framing;
    shuoke::AsciiCheck m_check;
    QByteArray m_rx;
    qint64 m_lastRxUs = 0;
    qint64 m_nowUs = 0;
    quint64 m_checksumErrors = 0;
    quint64 m_discarded = 0;
};

} // namespace dd
