#pragma once

namespace dd {

// Registers the resources of drivedesk_core (resources/core.qrc: dictionaries, alarm
// tables) under :/drivedesk/. drivedesk_core is a static library, so the linker drops its
// resource initialiser unless something calls it. Idempotent and thread-safe.
void ensureCoreResources();

} // namespace dd
