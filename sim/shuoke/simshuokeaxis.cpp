#include "sim/shuoke/simshuokeaxis.h"

#include <algorithm>
#include <cmath>

namespace dd {

namespace {

MotorModel::Config stepperConfig()
{
    MotorModel::Config c;
    c.countsPerRev = 4000.0; // 200 full steps x 20 microsteps
    c.maxSpeed = 100000.0;   // the protocol's speed limit
    c.acceleration = 50000.0;
    c.deceleration = 50000.0;
    c.positionErrorNoise = 0.0; // counters read exactly at rest
    c.errorPerSpeed = 1.0e-3;   // 5 pulses of following error at 5000 pulses/s (closed loop)
    c.errorPerAccel = 0.0;
    return c;
}

double toSeconds(qint64 us)
{
    return static_cast<double>(us) / 1e6;
}

} // namespace

SimShuokeAxis::SimShuokeAxis(bool closedLoop)
    : m_motor(stepperConfig())
    , m_closedLoop(closedLoop)
{
    m_motor.enable();
}

void SimShuokeAxis::setAcceleration(double v)
{
    m_motor.setAcceleration(std::max(v, 1.0));
}

void SimShuokeAxis::setDeceleration(double v)
{
    m_motor.setDeceleration(std::max(v, 1.0));
}

void SimShuokeAxis::advanceTo(qint64 nowUs)
{
    if (nowUs <= m_nowUs)
        return;
    m_nowUs = nowUs;
    const double target = toSeconds(nowUs);
    while (m_motor.time() + MotorModel::StepSeconds <= target + 1e-9) {
        if (!isRunning()) {
            m_motor.advanceTo(target); // at rest: one closed-form jump
            break;
        }
        stepOnce();
    }
}

void SimShuokeAxis::stepOnce()
{
    const double before = m_motor.positionExact();
    m_motor.advanceTo(m_motor.time() + MotorModel::StepSeconds);
    checkSwitches(before, m_motor.positionExact());
}

void SimShuokeAxis::checkSwitches(double before, double after)
{
    if (m_homing) {
        const double o = static_cast<double>(m_switches.origin);
        const bool searching = m_homingHow != Homing::LimitFirst || m_homingReversed;
        if (searching && (before - o) * (after - o) <= 0.0) {
            m_motor.emergencyStop();
            m_homing = false;
            if (m_homingHow != Homing::KeepCounters)
                zeroCounters();
            return;
        }
        const bool atLimit = (m_homingDir < 0 && leftLimit()) || (m_homingDir > 0 && rightLimit());
        if (!atLimit)
            return;
        if (!m_homingReversed) {
            m_homingReversed = true;
            m_homingDir = -m_homingDir;
            m_motor.runSpeed(m_homingDir * m_homingSpeed);
        } else {
            m_motor.emergencyStop();
            m_homing = false;
            m_homingFailed = true;
        }
        return;
    }
    const double v = m_motor.speed();
    if ((v < 0.0 && leftLimit()) || (v > 0.0 && rightLimit()))
        m_motor.emergencyStop();
}

void SimShuokeAxis::zeroCounters()
{
    m_absOffset = commanded();
    m_relOffset = commanded();
    m_clAbsOffset = m_motor.position();
    m_clRelOffset = m_motor.position();
}

void SimShuokeAxis::setPowered(bool on)
{
    if (on) {
        m_motor.enable();
        return;
    }
    m_homing = false;
    m_motor.disable();
}

void SimShuokeAxis::runSpeed(double speed)
{
    m_homing = false;
    m_motor.runSpeed(speed);
}

void SimShuokeAxis::changeSpeed(double speed)
{
    const double magnitude = std::abs(speed);
    if (m_motor.mode() == MotorModel::Mode::Speed) {
        const double dir = m_motor.targetSpeed() < 0.0 ? -1.0 : 1.0;
        m_motor.runSpeed(dir * magnitude);
    } else {
        m_motor.setMoveSpeed(std::max(magnitude, 1.0)); // a move never stalls on its way
    }
}

void SimShuokeAxis::moveRelative(qint64 distance, double speed)
{
    m_homing = false;
    m_motor.moveRelative(distance, std::max(speed, 1.0));
}

void SimShuokeAxis::moveToMotorPosition(qint64 target, double speed)
{
    m_homing = false;
    m_motor.moveAbsolute(target, std::max(speed, 1.0));
}

void SimShuokeAxis::stop()
{
    m_homing = false;
    m_motor.stop();
}

void SimShuokeAxis::emergencyStop()
{
    m_homing = false;
    m_motor.emergencyStop();
}

double SimShuokeAxis::cruiseSpeed() const
{
    return std::abs(m_motor.mode() == MotorModel::Mode::Speed ? m_motor.targetSpeed() : m_motor.moveSpeed());
}

void SimShuokeAxis::startHoming(bool positiveFirst, double speed, Homing how)
{
    m_homingHow = how;
    m_homingDir = positiveFirst ? 1 : -1;
    m_homingSpeed = std::max(std::abs(speed), 1.0);
    m_homingReversed = false;
    m_homingFailed = false;
    m_homing = m_motor.runSpeed(m_homingDir * m_homingSpeed); // not without the power stage
}

bool SimShuokeAxis::isRunning() const
{
    return m_homing || m_motor.isMoving();
}

bool SimShuokeAxis::leftLimit() const
{
    return m_motor.position() <= m_switches.leftLimit;
}

bool SimShuokeAxis::rightLimit() const
{
    return m_motor.position() >= m_switches.rightLimit;
}

bool SimShuokeAxis::origin() const
{
    return std::llabs(m_motor.position() - m_switches.origin) <= m_switches.originWidth;
}

void SimShuokeAxis::placeAt(qint64 position)
{
    m_homing = false;
    m_motor.emergencyStop();
    m_motor.setPosition(position);
    zeroCounters();
}

QJsonObject SimShuokeAxis::save() const
{
    QJsonObject o;
    o.insert(QStringLiteral("motorPosition"), static_cast<double>(m_motor.position()));
    o.insert(QStringLiteral("absoluteOffset"), static_cast<double>(m_absOffset));
    o.insert(QStringLiteral("relativeOffset"), static_cast<double>(m_relOffset));
    o.insert(QStringLiteral("closedLoopAbsoluteOffset"), static_cast<double>(m_clAbsOffset));
    o.insert(QStringLiteral("closedLoopRelativeOffset"), static_cast<double>(m_clRelOffset));
    o.insert(QStringLiteral("leftLimit"), static_cast<double>(m_switches.leftLimit));
    o.insert(QStringLiteral("rightLimit"), static_cast<double>(m_switches.rightLimit));
    o.insert(QStringLiteral("origin"), static_cast<double>(m_switches.origin));
    o.insert(QStringLiteral("originWidth"), static_cast<double>(m_switches.originWidth));
    return o;
}

void SimShuokeAxis::load(const QJsonObject &o)
{
    auto num = [&o](const char *key, qint64 fallback) {
        const QJsonValue v = o.value(QLatin1String(key));
        return v.isDouble() ? static_cast<qint64>(std::llround(v.toDouble())) : fallback;
    };
    m_switches.leftLimit = num("leftLimit", m_switches.leftLimit);
    m_switches.rightLimit = num("rightLimit", m_switches.rightLimit);
    m_switches.origin = num("origin", m_switches.origin);
    m_switches.originWidth = num("originWidth", m_switches.originWidth);
    m_homing = false;
    m_motor.emergencyStop();
    m_motor.setPosition(num("motorPosition", m_motor.position()));
    m_absOffset = num("absoluteOffset", m_absOffset);
    m_relOffset = num("relativeOffset", m_relOffset);
    m_clAbsOffset = num("closedLoopAbsoluteOffset", m_clAbsOffset);
    m_clRelOffset = num("closedLoopRelativeOffset", m_clRelOffset);
}

} // namespace dd
