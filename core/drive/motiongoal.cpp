#include "core/drive/motiongoal.h"

namespace dd {

MotionGoal MotionGoal::move(Family family, qint64 start, qint64 target)
{
    MotionGoal g;
    g.m_kind = Kind::Move;
    g.m_family = family;
    g.m_start = start;
    g.m_target = target;
    return g;
}

MotionGoal MotionGoal::home(Family family)
{
    MotionGoal g;
    g.m_kind = Kind::Home;
    g.m_family = family;
    return g;
}

qint64 MotionGoal::inPositionWindow(Family family)
{
    switch (family) {
    case Family::ServoCan: return 10;
    case Family::Shuoke: return 0;
    case Family::ServoModbus: return 10;
    }
    return 0;
}

qint64 MotionGoal::distanceToTarget(qint64 position) const
{
    return qAbs(m_target - position);
}

MotionGoal::Verdict MotionGoal::judge(qint64 position, bool stopSent) const
{
    if (m_kind == Kind::Home)
        return position == 0 && !stopSent ? Verdict::HomeFound : Verdict::HomeNotFound;
    if (distanceToTarget(position) <= inPositionWindow(m_family))
        return Verdict::Reached;
    // Short: still on the way from the start (or never left it); past: beyond the target.
    const qint64 way = m_target - m_start;
    const qint64 left = m_target - position;
    if (way == 0)
        return Verdict::Past;
    return (way > 0) == (left > 0) ? Verdict::Short : Verdict::Past;
}

} // namespace dd
