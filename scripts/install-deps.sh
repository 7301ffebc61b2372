#!/usr/bin/env bash
# Installs fairsurf's build and test dependencies from Debian 12's archive. Idempotent: packages that
# are already present are left alone, and apt-get runs only when something is missing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev            # dense + sparse linear algebra, unsupported GMRES/ILUT
  libopenmesh-dev          # halfedge editing for patch construction
  libsuitesparse-dev       # UMFPACK (umfpack_dl) sparse LU
  libmumps-seq-dev         # sequential MUMPS sparse LU (the default solver; builds without MPI)
  # MUMPS's MPI build over OpenMPI: --solver mumps-mpi spreads the factors over the ranks of
  # `mpirun -n N fairsurf ...` (FAIRSURF_MPI, docs/solvers.md); mpirun runs its tests (tests/mpi).
  # The PT-Scotch variant, because libmumps-dev's own build has no SCOTCH ordering (cmake/Mpi.cmake)
  openmpi-bin libopenmpi-dev libmumps-dev libmumps-ptscotch-dev
  libmetis-dev             # fill-reducing ordering for UMFPACK
  libopenblas-dev          # BLAS under MUMPS/UMFPACK (reference BLAS is 4-5x slower)
  libcli11-dev             # command-line parsing
  nlohmann-json3-dev       # --json output and logs
  libmuparser-dev          # user formulas f(H,K)
  libqhull-dev             # 3D Delaunay tetrahedralization of a hole's loop (CGAL's restricted search)
  libpng-dev               # PNG encoding for `fairsurf render`
  libstb-dev               # stb_truetype.h: glyph rasterization for render's title and colour bar
  fonts-dejavu-core        # DejaVu Sans, the font render draws its text with
  python3                  # standard library only: the demo's and the gallery's noise and measurements
  python3-dev pybind11-dev # the Python bindings (python/), built for Debian's /usr/bin/python3
  python3-numpy            # their arrays
  python3-pytest           # their tests (tests/python)
  python3-setuptools python3-pip  # `pip install --no-build-isolation .` (setup.py drives CMake)
  libomp-dev               # OpenMP runtime headers
  libgtest-dev libgmock-dev
  libbenchmark-dev
  clang-14                 # compiles the libFuzzer harnesses in fuzz/ (scripts/fuzz.sh)
  libclang-rt-14-dev       # libFuzzer and the ASan/UBSan runtimes clang-14 links them with
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ "${#missing[@]}" -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
echo "install-deps: all ${#packages[@]} packages present"
