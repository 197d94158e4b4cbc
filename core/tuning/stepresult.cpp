#include "core/tuning/stepresult.h"

namespace dd {

QString StepResult::outcomeId(Outcome outcome)
{
    switch (outcome) {
    case Outcome::Completed: return QStringLiteral("completed");
    case Outcome::Aborted: return QStringLiteral("aborted");
    case Outcome::Failed: return QStringLiteral("failed");
    }
    return {};
}

} // namespace dd
