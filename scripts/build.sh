#!/usr/bin/env bash
# Installs the dependencies (scripts/install-deps.sh) and builds fairsurf into build/ (Release).
# The CLI ends up at build/bin/fairsurf. Extra arguments are passed to CMake's configure step.
# FAIRSURF_BUILD_TARGET=T builds only target T and what it needs (scripts/demo.sh: the CLI, so that
# the first command does not compile the tests, benchmarks and bindings); unset, everything.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build -j "$(nproc)" ${FAIRSURF_BUILD_TARGET:+--target "$FAIRSURF_BUILD_TARGET"}
