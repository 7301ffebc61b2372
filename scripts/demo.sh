#!/usr/bin/env bash
# Installs, builds and runs fairsurf's main job on bundled data. Outputs go to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
fs=build/bin/fairsurf
mkdir -p out
run() { echo; echo "\$ fairsurf $*"; "$fs" "$@"; }
run info data/cgal_mech_holes_shark.off
run curvature data/spot.obj -o out/spot_curvature.ply --force
