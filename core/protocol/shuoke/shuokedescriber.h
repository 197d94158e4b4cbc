#pragma once

#include "core/protocol/framedescriber.h"
#include "core/protocol/shuoke/shuokeframe.h"

#include <QVariantMap>
#include <optional>

namespace dd {

// What a Shuoke frame means. framing "rtu" (default on serial), "ascii" or "plc" for serial
// frames; CAN frames always as the CAN framing. Options from the connection:
// "shuoke.byteOrder" ("little" | "big"), "shuoke.checksum" ("sum" | "twos-complement"),
// "shuoke.plcBase".
class ShuokeDescriber : public FrameDescriber
{
    Q_DECLARE_TR_FUNCTIONS(dd::FrameDescriber)

public:
    explicit ShuokeDescriber(const QString &framing = {}, const QVariantMap &options = {});

    QString describeSerial(Origin origin, const QByteArray &bytes) override;
    QString describeCan(Origin origin, const CanFrameData &frame) override;
    void reset() override { m_request.reset(); }

private:
    enum class SerialFraming { Rtu, Ascii, Plc };

    QString describeFrame(Origin origin, const shuoke::Frame &frame);
    QString valueText(quint8 command, const QByteArray &data, bool request) const;

    SerialFraming m_serialFraming = SerialFraming::Rtu;
    bool m_bigEndian = false;
    bool m_twosComplement = false;
    quint16 m_plcBase = 0;
    std::optional<shuoke::Frame> m_request;
};

} // namespace dd
