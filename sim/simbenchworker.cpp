#include "simbenchworker.h"

namespace dd {

SimBenchWorker::SimBenchWorker(QObject *parent)
    : QObject(parent)
{
}

SimBenchWorker::~SimBenchWorker() = default;

Error SimBenchWorker::build()
{
    // The family simulators are not in this build yet.
    return {ErrorCode::NotSupported, tr("The simulated drives are not available in this build.")};
}

} // namespace dd
