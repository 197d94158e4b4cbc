#include "sim/motor/loopgainparameter.h"

#include <algorithm>

namespace dd {

QString LoopGainParameter::roleId(Role role)
{
    switch (role) {
    case Role::SpeedKp: return QStringLiteral("speed-kp");
    case Role::SpeedKi: return QStringLiteral("speed-ki");
    case Role::PositionKp: return QStringLiteral("position-kp");
    case Role::SpeedFeedforward: return QStringLiteral("speed-feedforward");
    case Role::TorqueFeedforward: return QStringLiteral("torque-feedforward");
    case Role::Acceleration: return QStringLiteral("acceleration");
    }
    return {};
}

QString LoopGainParameter::unit(Role role)
{
    switch (role) {
    case Role::SpeedKp: return QStringLiteral("Hz");
    case Role::SpeedKi: return QStringLiteral("1/s");
    case Role::PositionKp: return QStringLiteral("1/s");
    case Role::SpeedFeedforward:
    case Role::TorqueFeedforward: return QStringLiteral("%");
    case Role::Acceleration: return QStringLiteral("r/min/ms");
    }
    return {};
}

void applyLoopGainParameters(const QList<LoopGainParameter> &table, const std::function<qint64(int)> &value,
                             MotorModel *motor)
{
    ServoLoop::Gains g = motor->gains();
    double acceleration = -1.0;
    for (const LoopGainParameter &p : table) {
        const double v = double(std::clamp(value(p.index), p.min, p.max));
        switch (p.role) {
        case LoopGainParameter::Role::SpeedKp: g.speedKpHz = v; break;
        case LoopGainParameter::Role::SpeedKi: g.speedKi = v; break;
        case LoopGainParameter::Role::PositionKp: g.positionKp = v; break;
        case LoopGainParameter::Role::SpeedFeedforward: g.feedforward = v / 100.0; break;
        case LoopGainParameter::Role::TorqueFeedforward: g.torqueFeedforward = v / 100.0; break;
        case LoopGainParameter::Role::Acceleration:
            acceleration = v * 1000.0 / 60.0 * motor->config().countsPerRev; // r/min/ms -> counts/s²
            break;
        }
    }
    const ServoLoop::Gains &now = motor->gains();
    if (g.speedKpHz != now.speedKpHz || g.speedKi != now.speedKi || g.positionKp != now.positionKp
        || g.feedforward != now.feedforward || g.torqueFeedforward != now.torqueFeedforward)
        motor->setGains(g);
    if (acceleration > 0.0 && acceleration != motor->config().acceleration) {
        motor->setAcceleration(acceleration);
        motor->setDeceleration(acceleration);
    }
}

} // namespace dd
