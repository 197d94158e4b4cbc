#include "core/drive/driveresult.h"

#include "core/drive/drivereply.h"

namespace dd {

DriveResult DriveResult::from(const DriveReply &reply)
{
    DriveResult r;
    r.error = reply.error();
    r.parameters = reply.parameters();
    r.writes = reply.writeResults();
    r.samples = reply.samples();
    r.sampleTimeUs = reply.sampleTimeUs();
    r.status = reply.status();
    r.info = reply.info();
    return r;
}

} // namespace dd
