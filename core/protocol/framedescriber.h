#pragma once

#include "common/family.h"
#include "protocol/canframedata.h"
#include "protocol/modbusrtu.h"
#include "protocol/shuokeframe.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QString>
#include <QVariantMap>
#include <optional>

namespace dd {

// Says in a few words what one frame on a link means, for the frame monitor, saved traffic
// logs and traces: "#1 run at 100 r/min", "#1 read PA0–PA19", "#1 PA0 = 7051, PA1 = 0, …",
// "#1 Query speed → 1000". Headless; one object per link, fed every frame of the link in
// the order they passed (a Modbus reply is only understood against the request before it,
// so the describer remembers the last request it saw).
//
// Per family and framing:
//   - servo-can (CAN): dd::servocan::decode; the station comes first ("#1").
//   - servo-modbus (serial): Modbus RTU (dd::modbusrtu) with the servo-modbus register
//     names (DP monitor mnemonics, PA parameters, EE operations).
//   - shuoke: framing "rtu" (default on serial), "ascii" or "plc" for serial frames, CAN
//     frames always as the CAN framing. Options from the connection: "shuoke.byteOrder"
//     ("little" | "big"), "shuoke.checksum" ("sum" | "twos-complement"), "shuoke.plcBase".
// A frame that does not decode reads "?" followed by the codec's technical reason in
// brackets. The words are translated (context dd::FrameDescriber, and the codecs' own
// contexts for command and register names) in the language current when describe() runs.
class FrameDescriber
{
    Q_DECLARE_TR_FUNCTIONS(dd::FrameDescriber)

public:
    enum class Origin { Host, Drive };   // TX is the host, RX the drive

    explicit FrameDescriber(Family family, const QString &framing = {},
                            const QVariantMap &options = {});

    Family family() const { return m_family; }

    QString describeSerial(Origin origin, const QByteArray &bytes);
    QString describeCan(Origin origin, const CanFrameData &frame);
    // Forgets the last request (e.g. after a gap in the traffic).
    void reset();

    static QString unknown(); // "?"

private:
    enum class SerialFraming { Rtu, Ascii, Plc };

    QString describeServoCan(Origin origin, const CanFrameData &frame) const;
    QString describeModbusRequest(const QByteArray &bytes);
    QString describeModbusReply(const QByteArray &bytes) const;
    QString describeShuokeSerial(Origin origin, const QByteArray &bytes);
    QString describeShuokeCan(Origin origin, const CanFrameData &frame);
    QString describeShuokeFrame(Origin origin, const shuoke::Frame &frame);
    QString shuokeValue(quint8 command, const QByteArray &data, bool request) const;

    Family m_family;
    SerialFraming m_serialFraming = SerialFraming::Rtu;
    bool m_bigEndian = false;
    bool m_twosComplement = false;
    quint16 m_plcBase = 0;
    std::optional<modbusrtu::Request> m_modbusRequest;
    std::optional<shuoke::Frame> m_shuokeRequest;
};

} // namespace dd
