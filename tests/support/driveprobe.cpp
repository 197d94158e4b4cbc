#include "tests/support/driveprobe.h"

#include "core/drive/drive.h"
#include "core/drive/drivereply.h"
#include "tests/support/replywait.h"

#include <cmath>

namespace dd::test {

double readChannel(Drive *drive, const QString &id, int ms)
{
    DriveReply *r = drive->readChannels({id});
    if (!waitForReply(r, ms) || !r->ok() || !r->samples().contains(id))
        return std::nan("");
    return r->samples().value(id);
}

bool readRunning(Drive *drive, int ms)
{
    DriveReply *r = drive->readStatus();
    return waitForReply(r, ms) && r->ok() && r->status().running;
}

} // namespace dd::test
