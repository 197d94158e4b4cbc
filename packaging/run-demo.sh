#!/usr/bin/env bash
# The main job with nothing plugged in: the DriveDesk workbench on the simulated bench
# (one drive of each family, in-process). Extra arguments go to `drivedesk`.
# Without a display (a server, a container), it shows the same bench through the CLI
# instead: scan, identity, a backup and a few seconds of live values, then exits.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${DRIVEDESK_BUILD_DIR:-$here/build}"
gui="$build/app/drivedesk"
cli="$build/app/drivedesk-cli"

if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ -x "$gui" ]; then
  exec "$gui" --demo "$@"
fi

echo "run-demo: no display found, so here is the simulated bench through drivedesk-cli."
echo "run-demo: on a desktop this command opens the workbench: $gui --demo"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
run() { echo; echo "\$ drivedesk-cli $*"; "$cli" "$@"; }
run --sim --sim-drives 1,2 --baud 115200 scan --from 1 --to 4
run --sim --family servo-modbus info
run --sim --family servo-modbus backup -o "$out/servo-modbus.json"
run --sim --family servo-can info
run --sim --family servo-can monitor speed,torque,current,bus-voltage --rate 10 --duration 1
run --sim --family shuoke get start-speed max-speed acceleration
