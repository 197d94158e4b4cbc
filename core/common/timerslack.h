#pragma once

namespace dd {

// Asks the OS to wake the calling thread's timers as close to their deadline as it can.
// Linux lets a sleeping thread's wake-up slip by its "timer slack" (50 us by default, to
// batch wake-ups); a link's thread waits on millisecond protocol timers (Qt's inter-frame
// delay, our gaps) many times per second, and on a busy machine the slip adds up to about
// 0.1 ms per transaction (measured: docs/performance.md, "Link speed"). The serial links
// call this in open(), in the thread they run in. Cheap after the first call in a thread.
// Elsewhere than on Linux it does nothing. Returns whether the slack is tightened.
bool tightenTimerSlack();

} // namespace dd
