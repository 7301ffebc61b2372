#!/usr/bin/env bash
# Installs, builds (warnings as errors) and runs the whole test suite. This is what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh -DFAIRSURF_WERROR=ON
cd build
ctest --output-on-failure -j "$(nproc)" --timeout 900
