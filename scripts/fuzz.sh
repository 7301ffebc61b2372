#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/, clang-14 with ASan + UBSan) in build-fuzz/ and runs each
# for FUZZ_SECONDS seconds (default 25) on a corpus seeded from data/ and from conversions of a small
# mesh into every format. A crash stops the script with the harness's report; its input is written
# to build-fuzz/artifacts/ (keep it under tests/regressions/ once fixed). Needs build/bin/fairsurf
# (scripts/build.sh) for the seeds. Skipped, with a note, where clang-14 is not installed.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${FUZZ_SECONDS:-25}"
if ! command -v clang++-14 >/dev/null; then
  echo "fuzz: clang++-14 is not installed (scripts/install-deps.sh installs it); skipped"
  exit 0
fi

export CCACHE_BASEDIR="$PWD"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang-14 \
  -DCMAKE_CXX_COMPILER=clang++-14 "${launcher[@]}" -DFAIRSURF_FUZZ=ON -DFAIRSURF_BUILD_TESTS=OFF \
  -DFAIRSURF_BUILD_BENCH=OFF -DFAIRSURF_WERROR=ON >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target fuzz_all

# Seeds: the bundled files of each format under 100 kB, and one small mesh written in each format
# and encoding (data/ has no STL and only one binary PLY).
seeds=build-fuzz/seeds
rm -rf "$seeds" && mkdir -p "$seeds"
cli=build/bin/fairsurf
small=data/hourglass_ico.obj
for ext in obj off ply stl; do
  mkdir -p "$seeds/$ext"
  find data -maxdepth 1 -name "*.$ext" -size -100k -exec cp {} "$seeds/$ext/" \;
  "$cli" convert "$small" -o "$seeds/$ext/small_binary.$ext" --force >/dev/null
  "$cli" convert "$small" -o "$seeds/$ext/small_ascii.$ext" --ascii --force >/dev/null
done
cp tests/regressions/* "$seeds/off/" 2>/dev/null || true

run() {  # harness, seed format
  local harness=$1 format=$2 corpus=build-fuzz/corpus/$1 log=build-fuzz/$1.log rc=0
  mkdir -p "$corpus" build-fuzz/artifacts
  echo "fuzz: $harness for ${seconds} s"
  "build-fuzz/bin/$harness" "$corpus" "$seeds/$format" -max_total_time="$seconds" -max_len=65536 \
    -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/ \
    >"$log" 2>&1 || rc=$?
  grep -E "^stat::(number_of_executed_units|new_units_added)" "$log" || true
  if [ "$rc" -ne 0 ]; then
    tail -n 60 "$log"
    echo "fuzz: $harness failed (exit $rc); the input is in build-fuzz/artifacts/"
    return "$rc"
  fi
}
for format in obj off ply stl; do run "fuzz_read_$format" "$format"; done
run fuzz_repair off
echo "fuzz: no crash"
