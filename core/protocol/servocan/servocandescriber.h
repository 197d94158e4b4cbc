#pragma once

#include "core/protocol/framedescriber.h"

namespace dd {

// What a servo-can frame means (dd::servocan::decode); the station comes first ("#1").
class ServoCanDescriber : public FrameDescriber
{
    Q_DECLARE_TR_FUNCTIONS(dd::FrameDescriber)

public:
    QString describeCan(Origin origin, const CanFrameData &frame) override;
};

} // namespace dd
