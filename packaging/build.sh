#!/usr/bin/env bash
# Configure (once) and build DriveDesk into ./build with at most two jobs.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${DRIVEDESK_BUILD_DIR:-$here/build}"
preset_args=(-G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo)
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$here" -B "$build" "${preset_args[@]}" "$@"
fi
cmake --build "$build" -j2
