#include "ui/bus/driveinfo.h"

#include "ui/common/displaytext.h"

#include "core/drive/drive.h"
#include "core/drive/drivehub.h"
#include "core/drive/drivereply.h"

#include <memory>

namespace dd {

QList<Capability> DriveInfo::allCapabilities()
{
    return {Capability::ReadParameters, Capability::WriteParameters,
            Capability::Monitor,        Capability::Jog,
            Capability::MoveRelative,   Capability::MoveAbsolute,
            Capability::Home,           Capability::SetPosition,
            Capability::Enable,         Capability::Stop,
            Capability::EmergencyStop,  Capability::ReadAlarm,
            Capability::ClearAlarm,     Capability::EeOperations};
}

QString DriveInfo::capabilityName(Capability c)
{
    return DisplayText::capabilityName(c);
}

void fetchDriveInfo(DriveHub *hub, int connectionId, int address,
                    std::function<void(const DriveInfo &, const Error &)> done)
{
    // Filled on the I/O thread; read on this thread only in the completion callback, which
    // the hub posts after the reply has finished (the queued event orders the accesses).
    auto info = std::make_shared<DriveInfo>();
    info->connectionId = connectionId;
    info->address = address;
    const auto capture = [info](Drive &d) {
        info->identity = d.identity();
        info->capabilities = d.capabilities();
        info->channels = d.channels();
        info->status = d.status();
        info->unsupportedReasons.clear();
        for (Capability c : DriveInfo::allCapabilities())
            if (!d.hasCapability(c))
                info->unsupportedReasons.insert(c, d.unsupportedReason(c));
        info->valid = true;
    };
    hub->run(
        connectionId, address,
        [capture](Drive &d) {
            capture(d); // even if the identity read fails, the static facts are known
            DriveReply *reply = d.refreshIdentity();
            if (reply) {
                Drive *drive = &d;
                QObject::connect(reply, &DriveReply::finished, reply, [capture, drive] { capture(*drive); });
            }
            return reply;
        },
        [info, done](const DriveResult &result) {
            if (done)
                done(*info, result.error);
        });
}

} // namespace dd
