#!/usr/bin/env bash
# Renders the PNG sizes of the application icon from drivedesk.svg (rsvg-convert, Debian
# package librsvg2-bin). The PNGs are committed, so that building needs no SVG renderer;
# run this after changing the SVG.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
for size in 16 22 24 32 48 64 128 256; do
  rsvg-convert -w "$size" -h "$size" "$here/drivedesk.svg" -o "$here/drivedesk-$size.png"
done
