#pragma once

#include <QLoggingCategory>

namespace dd {

// Logging categories of the simulator: "drivedesk.sim" for events (open, close, errors,
// faults) and "drivedesk.sim.frames" for hex dumps of every chunk and reply.
Q_DECLARE_LOGGING_CATEGORY(lcSim)
Q_DECLARE_LOGGING_CATEGORY(lcSimFrames)

} // namespace dd
