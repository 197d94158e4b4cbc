#pragma once

#include "core/common/family.h"

#include <QtGlobal>

namespace dd {

// What a move or a homing was asked to reach, and whether the axis, at rest, reached it
// ("done" means reached; the GUI's Motion tab and the CLI's move / home judge the same way):
//   a move is done only when the axis rests at its target within the family's in-position
//   window (inPositionWindow());
//   a homing is done only when the drive reports the home found: the families that home
//   (shuoke 0x3E) zero their position counters at the origin, so the position reads 0 at
//   rest, and no stop was sent while it ran (a STOP at 0 did not find the origin).
class MotionGoal
{
public:
    enum class Kind { Move, Home };
    enum class Verdict {
        Reached,     // a move: at its target
        Short,       // a move: at rest before its target
        Past,        // a move: at rest beyond its target
        HomeFound,   // a homing: the origin was found
        HomeNotFound // a homing: at rest elsewhere, or stopped
    };

    static MotionGoal move(Family family, qint64 start, qint64 target);
    static MotionGoal home(Family family);

    // How far from its target an axis at rest still counts as there, in the family's
    // position unit. Neither seed names a drive's in-position window: servo-can 10 counts
    // (0.1 % of a turn at 10000 counts/turn, above the simulator's half count and a servo's
    // usual default), shuoke 0 pulses (the commanded pulse counter ends exactly on its target).
    static qint64 inPositionWindow(Family family);

    Kind kind() const { return m_kind; }
    qint64 start() const { return m_start; }
    qint64 target() const { return m_target; }
    // At rest at `position`; `stopSent`: a stop (STOP, this drive's stop) went out meanwhile.
    Verdict judge(qint64 position, bool stopSent = false) const;
    // How far the axis at `position` is from the target (always >= 0).
    qint64 distanceToTarget(qint64 position) const;

private:
    Kind m_kind = Kind::Move;
    Family m_family = Family::ServoModbus;
    qint64 m_start = 0;
    qint64 m_target = 0;
};

} // namespace dd
