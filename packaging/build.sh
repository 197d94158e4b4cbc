#!/usr/bin/env bash
# Configure (once) and build the three programs (drivedesk, drivedesk-cli, drivedesk-sim)
# into ./build with at most two jobs: what run-demo.sh needs, not the test suite
# (packaging/test.sh builds everything; `cmake --build build --target package` makes the
# Debian package). Extra arguments go to the first configure.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${DRIVEDESK_BUILD_DIR:-$here/build}"
# the default preset's flags (CMakePresets.json): -O2, line tables only
preset_args=(-G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG"
             "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG")
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$here" -B "$build" "${preset_args[@]}" "$@"
fi
targets=(drivedesk-cli drivedesk-sim)
# the GUI unless it was configured out (-DDRIVEDESK_BUILD_GUI=OFF)
if grep -q '^build app/drivedesk:' "$build/build.ninja"; then
  targets=(drivedesk "${targets[@]}")
fi
cmake --build "$build" -j2 --target "${targets[@]}"
