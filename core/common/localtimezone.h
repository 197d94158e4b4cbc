#pragma once

namespace dd {

// Call first thing in main(), before any thread starts. Where the TZ environment variable
// is not set, sets it to ":/etc/localtime" — the zone glibc uses anyway — so that glibc's
// tzset() stops looking at /etc/localtime again on every call. Qt calls tzset() whenever a
// QDateTime is made in local time, and Qt's virtualcan plugin makes one for every frame it
// receives (its timestamp): with TZ unset that was a stat() of /etc/localtime per frame,
// 10.7 % of the CPU time of a servo-can monitor against the simulator (perf; docs/
// performance.md, "Link speed"). Consequence: a change of the system's time zone while the
// program runs is seen after a restart. Does nothing where TZ is set, and off Linux.
// Returns whether it set TZ.
bool pinLocalTimeZone();

} // namespace dd
