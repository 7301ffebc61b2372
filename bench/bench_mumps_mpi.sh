#!/usr/bin/env bash
# Runs bench_mumps_mpi (its header says what it measures) at 1, 2 and 4 ranks on this machine and
# prints one table row per run: time per step and peak memory per rank, and how MUMPS's factorization
# memory divides (busiest rank against an even share of all ranks' total); assembled_MB is rank 0's
# resident memory with the matrix assembled, before the solver exists.
#   bench/bench_mumps_mpi.sh [BUILD_DIR] [SUBDIVISIONS...]     (default: build-mpi, 7 = 164k unknowns)
# BUILD_DIR is a build with -DFAIRSURF_MPI=ON (the default build has no mumps-mpi), e.g.
#   cmake -S . -B build-mpi -DCMAKE_BUILD_TYPE=Release -DFAIRSURF_MPI=ON -DFAIRSURF_BUILD_BENCH=ON
#   cmake --build build-mpi -j2 --target bench_mumps_mpi
# 1 rank runs the sequential path (--solver mumps) with two BLAS threads; N ranks run mumps-mpi with
# one BLAS thread each, so every run uses the same two cores.
set -euo pipefail
build=${1:-build-mpi}
shift || true
sizes=("${@:-7}")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
printf '%-9s %-5s %-9s %-7s %-13s %-17s %-12s %-12s %-16s %s\n' unknowns ranks analyze_s step_s factor_MB_all factor_MB_busiest busiest/even assembled_MB peak_MB_busiest peak_MB_per_rank
for s in "${sizes[@]}"; do
  steps=$([ "$s" -ge 8 ] && echo 1 || echo 2)
  for n in 1 2 4; do
    if [ "$n" -eq 1 ]; then solver=mumps threads=2; else solver=mumps-mpi threads=1; fi
    out=$(OPENBLAS_NUM_THREADS=$threads mpirun -n "$n" --oversubscribe "$build/bin/bench_mumps_mpi" "$s" "$steps" "$solver")
    echo "$out" | awk -v n="$n" '
      /^result/ { for (i = 2; i < NF; i += 2) r[$i] = $(i + 1) }
      /^rank/ { peak[$2] = $4; if ($4 > max) max = $4 }
      END {
        per = ""; for (k = 0; k < n; ++k) per = per (k ? "/" : "") peak[k]
        printf "%-9s %-5s %-9s %-7s %-13s %-17s %-12.2f %-12s %-16s %s\n", r["unknowns"], n, r["analyze_s"], r["step_s"],
               r["factor_mb_all"], r["factor_mb_busiest"], r["factor_mb_busiest"] / (r["factor_mb_all"] / n),
               r["assembled_mb"], max, per
      }'
  done
done
