#!/usr/bin/env bash
# Takes the documentation screenshots: the main window in demo mode (simulated drives, no
# hardware), in English and in Chinese, under a virtual X server (xvfb-run), into
# docs/screenshots/. The application grabs its own window (--screenshot FILE after
# --screenshot-delay seconds) and quits, so the pictures are the same on every run.
# Settings go to a temporary directory: the user's own are neither read nor changed.
#   packaging/screenshots.sh [build-dir]
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-${DRIVEDESK_BUILD_DIR:-$here/build}}"
app="$build/app/drivedesk"
out="$here/docs/screenshots"
delay="${DRIVEDESK_SCREENSHOT_DELAY:-6}"

if [ ! -x "$app" ]; then
  echo "screenshots: $app not found; build first (packaging/build.sh)" >&2
  exit 1
fi
command -v xvfb-run >/dev/null || { echo "screenshots: xvfb-run is missing (apt install xvfb)" >&2; exit 1; }
mkdir -p "$out"
settings="$(mktemp -d)"
trap 'rm -rf "$settings"' EXIT

shoot() {   # shoot LANG PANEL FILE [FAMILY: the drive to select] [a file to open in its tabs]
  local drive=() open=()
  [ -n "${4:-}" ] && drive=(--drive "$4")
  [ -n "${5:-}" ] && open=("$5")
  XDG_CONFIG_HOME="$settings/$1" QT_LOGGING_RULES="*.debug=false;qt.canbus.*=false" \
    xvfb-run --auto-servernum --server-args="-screen 0 1280x720x24" \
    "$app" -geometry 1280x720+0+0 --demo --lang "$1" --panel "$2" "${drive[@]}" --screenshot "$out/$3" \
      --screenshot-delay "$delay" "${open[@]}"
  echo "screenshots: $out/$3"
}

# A laptop's 1280x720, every tab in both languages.
for lang in en zh_CN; do
  shoot "$lang" overview "main-window-$lang.png"
  shoot "$lang" trend "trend-$lang.png"
  shoot "$lang" parameters "parameters-$lang.png"
  shoot "$lang" backup "backup-$lang.png"
  shoot "$lang" alarms "alarms-$lang.png"
  shoot "$lang" ee "eeprom-$lang.png"
  shoot "$lang" motion "motion-$lang.png" servo-can
done
# The Tuning tab with a run in it: a velocity step taken by the CLI on its own simulator.
run="$settings/velocity-step.ddrun"
QT_LOGGING_RULES="*.debug=false;qt.canbus.*=false" "$build/app/drivedesk-cli" --sim --family servo-can \
  step velocity 500 --duration 0.4 --max-speed 800 --max-travel 1000000 -o "$run" >/dev/null
shoot en tuning tuning-en.png servo-can "$run"
shoot zh_CN tuning tuning-zh_CN.png servo-can "$run"
# The commissioning record (docs/record.md): page 1 of a record of two simulated servo-modbus
# drives (one with a parameter written and verified), and page 3 of a servo-can record with
# the run above. Rendered with pdftoppm (poppler-utils).
if command -v pdftoppm >/dev/null; then
  cli() { XDG_DATA_HOME="$settings/data" QT_LOGGING_RULES="*.debug=false;qt.canbus.*=false" "$build/app/drivedesk-cli" "$@"; }
  printf '%s' '{"machine": "Press line 3", "customer": "ACME Stamping", "site": "Hall B", "engineer": "Li Wei", "notes": "Axis 2 retuned after the gearbox change."}' >"$settings/header.json"
  cli --sim-state "$settings/bench.json" --sim-drives 1,2 --family servo-modbus --address 2 set PA12=300 >/dev/null
  cli --sim-state "$settings/bench.json" --sim-drives 1,2 --family servo-modbus report --all \
    --header "$settings/header.json" -o "$settings/record.pdf" >/dev/null
  pdftoppm -r 80 -f 1 -l 1 -png -singlefile "$settings/record.pdf" "$out/record-page1"
  cli --sim --family servo-can report --runs "$run" --header "$settings/header.json" -o "$settings/run.pdf" >/dev/null
  pdftoppm -r 80 -f 3 -l 3 -png -singlefile "$settings/run.pdf" "$out/record-run"
  echo "screenshots: $out/record-page1.png $out/record-run.png"
else
  echo "screenshots: pdftoppm is missing (apt install poppler-utils): record pictures not taken" >&2
fi
