#!/usr/bin/env bash
# Installs, builds (warnings as errors) and runs the whole test suite. This is what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh -DFAIRSURF_WERROR=ON
# The Python bindings' pytest suite runs in ctest as python_bindings; fail rather than lose it
# silently when pybind11, NumPy or pytest were not found for /usr/bin/python3.
if ! (cd build && ctest -N -R '^python_bindings$' | grep -q 'Total Tests: 1'); then
  echo "test.sh: the Python tests are not configured (see docs/python.md)" >&2
  exit 1
fi
(cd build && ctest --output-on-failure -j "$(nproc)" --timeout 900)
# The distributed solver (--solver mumps-mpi, docs/solvers.md) is a build of its own: MPI MUMPS and
# the sequential one cannot share a process. Build what its tests need (the library, the CLI, the
# MPI probe) in build-mpi and run them: 2 ranks under mpirun against the sequential results.
cmake -S . -B build-mpi -DCMAKE_BUILD_TYPE=Release -DFAIRSURF_MPI=ON -DFAIRSURF_WERROR=ON -DFAIRSURF_BUILD_BENCH=OFF
cmake --build build-mpi -j "$(nproc)" --target test_mpi
(cd build-mpi && ctest --output-on-failure --timeout 900 -R '^Mpi')
# Bounded fuzzing: each libFuzzer harness (readers, repair) for FUZZ_SECONDS (25 s by default), then
# random mutations of small meshes through every CLI command for 60 s; any crash or hang fails.
bash scripts/fuzz.sh
python3 scripts/fuzz_cli.py build/bin/fairsurf --seconds "${FUZZ_CLI_SECONDS:-60}" --seed 1
