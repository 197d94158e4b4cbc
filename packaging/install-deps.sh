#!/usr/bin/env bash
# Installs everything DriveDesk needs to build, run and test on Debian 12 (bookworm).
# Idempotent: when every package is present it only checks and returns (no apt calls).
# Run as root, or as a user with sudo.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config ccache git
  qt6-base-dev qt6-base-dev-tools qt6-serialport-dev qt6-serialbus-dev libqt6serialbus6-bin
  qt6-charts-dev qt6-svg-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n
  libgl-dev libqt6opengl6-dev libxkbcommon-dev libvulkan-dev
  libmodbus-dev mbpoll python3-pymodbus python3-serial-asyncio socat libkissfft-dev
  clang libclang-rt-14-dev clang-format
  xvfb xauth fonts-noto-cjk
  help2man lintian desktop-file-utils appstream shared-mime-info bash-completion
  poppler-utils python3-jsonschema   # the commissioning record's tests: pdftotext, the JSON schema
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
