#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Quick start for rsfcycle on Debian 12.
#   bash quickstart.sh run    install missing packages, build (Release), run
#                             the 2D laboratory wedge prm/wedge-2d.prm on
#                             RANKS (default 2) MPI ranks
#   bash quickstart.sh test   same setup, check formatting, run the tests
# JOBS (default 2) sets the parallel build and test jobs.
set -euo pipefail
cd "$(dirname "$0")"

mode=${1:-}
if [[ $mode != run && $mode != test ]]; then
  echo "usage: bash quickstart.sh run|test" >&2
  exit 2
fi
jobs=${JOBS:-2}

# 1. Debian packages (only if one is missing; needs root). OpenBLAS (the
# single-threaded build: MPI ranks are the parallelism) becomes the system's
# BLAS: the Green's-function method's operator build (CHOLMOD) and products
# (hmat-oss) run 3.5x faster on it than on the reference BLAS
# (benchmarks/seas-bp5/README.md).
packages=(libdeal.ii-dev libsuitesparse-dev libhmat-oss-dev libopenblas0-serial
  openmpi-bin cmake g++ make numdiff python3-matplotlib python3-numpy
  python3-pandas python3-pytest clang-format-14 git gmsh)
# the tests open HDF5/XDMF and VTU snapshots in ParaView (pvbatch)
if [[ $mode == test ]]; then
  packages+=(paraview python3-paraview xvfb xauth)
fi
missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [[ $status == installed ]] || missing+=("$p")
done
if ((${#missing[@]})); then
  if ((EUID != 0)); then
    echo "missing Debian packages (run as root to install): ${missing[*]}" >&2
    exit 1
  fi
  apt-get update
  DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends \
    "${missing[@]}"
fi

# 2. Configure and build (Release); the meshes too large for git are made
# from their .geo (gmsh writes them byte for byte the same, in a second).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"
if [[ ! -f prm/meshes/seas-bp4.msh ]]; then
  gmsh -3 -format msh22 -setnumber whole 1 prm/meshes/seas-bp5.geo \
    -o prm/meshes/seas-bp4.msh >/dev/null
fi

# 3. Run or test.
if [[ $mode == run ]]; then
  # --force: the demo run replaces the folder of an earlier demo run.
  # RANKS (default 2) MPI ranks (README.md gives the demo's wall time).
  # Open MPI refuses root unless told.
  ranks=${RANKS:-2}
  if ((EUID == 0)); then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  fi
  mpirun -np "$ranks" --oversubscribe build/rsfcycle --force prm/wedge-2d.prm
  outdir=$(sed -n 's/^ *set Output directory *= *//p' prm/wedge-2d.prm)
  echo "Output: $PWD/$outdir (parameters.prm, log.txt, time-series.csv," \
    "base-profile.csv, events.csv, summary.txt, solution.pvd)"
else
  format=clang-format
  command -v clang-format >/dev/null || format=clang-format-14
  find include source tests \( -name '*.h' -o -name '*.cc' \) -print0 |
    xargs -0 -r "$format" --dry-run -Werror ||
    { echo "Formatting check failed: run $format -i on them" >&2; exit 1; }
  echo "Formatting: OK"
  cd build
  exec ctest --output-on-failure -j"$jobs"
fi
