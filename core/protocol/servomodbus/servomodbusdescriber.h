#pragma once

#include "core/protocol/framedescriber.h"
#include "core/protocol/modbus/modbusrtu.h"

#include <optional>

namespace dd {

// What a servo-modbus frame means: Modbus RTU (dd::modbusrtu) with the family's register
// names (DP monitor mnemonics, PA parameters, EE operations). A reply is read against the
// request before it.
class ServoModbusDescriber : public FrameDescriber
{
    Q_DECLARE_TR_FUNCTIONS(dd::FrameDescriber)

public:
    QString describeSerial(Origin origin, const QByteArray &bytes) override;
    void reset() override { m_request.reset(); }

private:
    QString describeRequest(const QByteArray &bytes);
    QString describeReply(const QByteArray &bytes) const;

    std::optional<modbusrtu::Request> m_request;
};

} // namespace dd
