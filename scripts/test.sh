#!/usr/bin/env bash
# Installs, builds (warnings as errors) and runs the whole test suite. This is what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh -DFAIRSURF_WERROR=ON
(cd build && ctest --output-on-failure -j "$(nproc)" --timeout 900)
# Bounded fuzzing: each libFuzzer harness (readers, repair) for FUZZ_SECONDS (25 s by default), then
# random mutations of small meshes through every CLI command for 60 s; any crash or hang fails.
bash scripts/fuzz.sh
python3 scripts/fuzz_cli.py build/bin/fairsurf --seconds "${FUZZ_CLI_SECONDS:-60}" --seed 1
