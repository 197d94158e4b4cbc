#pragma once

namespace dd {

// Call first thing in main(), before the application object and any thread. Where the
// QT_NO_GLIB environment variable is not set, sets it, so that Qt gives every thread its
// plain poll() event dispatcher (QEventDispatcherUNIX) instead of the one on GLib's main
// loop. Called by drivedesk-cli, drivedesk-sim and the benches; not by the GUI, which keeps
// GLib's loop for the desktop's platform theme (GTK's native file dialogs run on it): its
// trends ask for the GUI's rates, which the links reach under either dispatcher
// (bench_speed --gui-rates).
//
// Why: a link waits on the wire many hundred times a second (microsecond timers, serial and
// CAN sockets). Measured against the simulator (bench_speed, 2-core VM, quiet machine,
// 3 × 5 runs each; docs/performance.md, "The event dispatcher"): with the GLib dispatcher
// the servo-can monitor ran at 547-865 Hz, stalling for 2-14 ms several hundred times in
// 2 s while both threads were idle; with the plain dispatcher 823-872 Hz in every run. The
// servo-modbus monitor at 115200 baud: 167-178 Hz against 169-178 Hz, 93-95 % against 96 %
// of the wire's rate. Nothing in the command-line programs needs GLib's loop. Setting
// QT_NO_GLIB to an empty value keeps GLib's dispatcher (the variable is set, so it is left
// alone, and Qt only honours a non-empty one). Does nothing off Linux/Unix.
// Returns whether it set the variable.
bool preferPlainEventDispatcher();

} // namespace dd
