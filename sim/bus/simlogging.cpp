#include "sim/bus/simlogging.h"

namespace dd {

Q_LOGGING_CATEGORY(lcSim, "drivedesk.sim")
Q_LOGGING_CATEGORY(lcSimFrames, "drivedesk.sim.frames", QtWarningMsg)

} // namespace dd
