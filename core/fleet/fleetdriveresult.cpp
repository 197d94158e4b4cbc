#include "core/fleet/fleetdriveresult.h"

namespace dd {

QString FleetDriveResult::stateId(State state)
{
    switch (state) {
    case State::Pending: return QStringLiteral("pending");
    case State::Running: return QStringLiteral("running");
    case State::Done: return QStringLiteral("done");
    case State::Failed: return QStringLiteral("failed");
    case State::NotAttempted: return QStringLiteral("not-attempted");
    }
    return {};
}

} // namespace dd
