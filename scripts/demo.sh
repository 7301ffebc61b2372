#!/usr/bin/env bash
# Installs, builds and runs fairsurf's main job on bundled data.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
fs=build/bin/fairsurf
mkdir -p out
echo "== fairsurf info data/cgal_mech_holes_shark.off"
$fs info data/cgal_mech_holes_shark.off
