#include "core/params/paramslog.h"

namespace dd {

Q_LOGGING_CATEGORY(lcParams, "drivedesk.params")

} // namespace dd
