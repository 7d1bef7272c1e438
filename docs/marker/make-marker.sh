#!/usr/bin/env sh
# Regenerates the default printable marker (ArUco MIP_36h12, id 0, 100 mm black square) beside
# this script with skinlab's own generator. Run from anywhere after `gradle -q :desktop:installDist`.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
skinlab="$here/../../desktop/build/install/skinlab/bin/skinlab"
"$skinlab" marker --dictionary aruco_mip_36h12 --id 0 --size-mm 100 \
  --pdf "$here/skinlab-marker-36h12-id0-100mm.pdf" --png "$here/skinlab-marker-36h12-id0-100mm.png" --dpi 300
