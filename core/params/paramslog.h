#pragma once

#include <QLoggingCategory>

namespace dd {

Q_DECLARE_LOGGING_CATEGORY(lcParams) // "drivedesk.params"

} // namespace dd
