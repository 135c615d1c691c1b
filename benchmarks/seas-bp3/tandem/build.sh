#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Builds tandem (github.com/TEAR-ERC/tandem, a discontinuous-Galerkin SEAS
# code) outside the repository, as a third code for BP3-QD next to HBI.
#
#   benchmarks/seas-bp3/tandem/build.sh PREFIX     (or TANDEM_PREFIX=PREFIX in the environment)
#
# tandem needs PETSc with 64-bit indices, as its CI builds it (3.22,
# --with-64-bit-indices): against Debian's PETSc 3.18 (32-bit indices) it
# compiles (with petsc-3.18.patch) but its time loop fails, even on its own
# manufactured solution (README.md). So PETSc v3.22.5 is built from source
# into PREFIX/petsc/install (no downloads: no MUMPS; tandem then uses
# PETSc's own LU), and GKlib, METIS and ParMETIS (not in Debian's main)
# into PREFIX/tandem-deps. tandem is configured for 2D, polynomial degree
# 4, ARCH=hsw (noarch without AVX2). petsc-3.18.patch is applied as well:
# it is inert with PETSc 3.22, and it keeps the tree the one that ran.
# Every source is pinned below; they come from GitHub, or from MIRROR if
# set (a folder of bare mirrors MIRROR/OWNER+NAME/repo). Writes
# PREFIX/tandem/build-petsc322/app/tandem. About 25 minutes on 2 cores.
set -euo pipefail
case "${1:-}" in -h|--help) sed -n '3,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0;; esac
PREFIX=${1:-${TANDEM_PREFIX:-}}
[ -n "$PREFIX" ] || { echo "usage: $0 PREFIX (where tandem, its PETSc and ParMETIS are built; or TANDEM_PREFIX)" >&2; exit 2; }
TANDEM_COMMIT=b75f66692d299673bf85632ed71e2a7da71ff2e0  # 2026-06-29
MNEME_COMMIT=fa175cffe4a22edc9efce5a7618610538936983b   # tandem's submodule pin
YATETO_COMMIT=6920a2b602539baa503a959ab396f4918b2b439c  # tandem's submodule pin
GKLIB_COMMIT=e2856c2f595b153ca1ce9258c5301dbabc4f39f5
METIS_COMMIT=a6e6a2cfa92f93a3ee2971ebc9ddfc3b0b581ab2
PARMETIS_COMMIT=8ee6a372ca703836f593e3c450ca903f04be14df
PETSC_COMMIT=9fe822445bcdd45fb93170ff68fa7403d3f52f09   # v3.22.5

DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends \
  liblua5.3-dev libeigen3-dev zlib1g-dev libopenmpi-dev liblapack-dev gmsh \
  python3-numpy cmake g++ make > /dev/null

source_of() {  # owner/name -> a git URL
  if [ -n "${MIRROR:-}" ] && [ -d "$MIRROR/${1/\//+}/repo" ]; then echo "$MIRROR/${1/\//+}/repo"
  else echo "https://github.com/$1.git"; fi
}
# a pinned tree without the large test graphs (the mirror has no blobs for them)
export_tree() {  # owner/name commit dir
  rm -rf "$3"; mkdir -p "$3"
  local tmp; tmp=$(mktemp -d)
  git clone -q --bare "$(source_of "$1")" "$tmp/repo.git"
  git --git-dir="$tmp/repo.git" archive "$2" -- . ':!graphs' | tar -x -C "$3"
  rm -rf "$tmp"
}

DEPS=$PREFIX/tandem-deps
SRC=$PREFIX/tandem-src
if [ ! -f "$DEPS/lib/libparmetis.so" ]; then
  export_tree KarypisLab/GKlib $GKLIB_COMMIT "$SRC/GKlib"
  export_tree KarypisLab/METIS $METIS_COMMIT "$SRC/METIS"
  export_tree KarypisLab/ParMETIS $PARMETIS_COMMIT "$SRC/ParMETIS"
  (cd "$SRC/GKlib" && make config prefix="$DEPS" cc=gcc openmp=set shared=set && make -j2 install) > "$SRC/gklib.log" 2>&1
  (cd "$SRC/METIS" && make config prefix="$DEPS" gklib_path="$DEPS" shared=1 && make -j2 install) > "$SRC/metis.log" 2>&1
  (cd "$SRC/ParMETIS" && make config prefix="$DEPS" gklib_path="$DEPS" metis_path="$DEPS" shared=1 cc=mpicc &&
     make -j2 install) > "$SRC/parmetis.log" 2>&1
fi

PETSC=$PREFIX/petsc
if [ ! -f "$PETSC/install/lib/pkgconfig/PETSc.pc" ]; then
  rm -rf "$PETSC/src"
  git clone -q "$(source_of petsc/petsc)" "$PETSC/src"
  git -C "$PETSC/src" checkout -q $PETSC_COMMIT
  (cd "$PETSC/src" &&
   ./configure --with-fortran-bindings=0 --with-debugging=0 --with-memalign=32 \
     --with-64-bit-indices CC=mpicc CXX=mpicxx --with-fc=0 COPTFLAGS=-O3 CXXOPTFLAGS=-O3 \
     --with-hdf5=0 --with-x=0 --prefix="$PETSC/install" &&
   make PETSC_DIR="$PETSC/src" PETSC_ARCH=arch-linux-c-opt MAKE_NP=2 all &&
   make PETSC_DIR="$PETSC/src" PETSC_ARCH=arch-linux-c-opt install) > "$PETSC/build.log" 2>&1 ||
    { tail -20 "$PETSC/build.log"; exit 1; }
fi

T=$PREFIX/tandem
if [ ! -d "$T/src/.git" ]; then
  git clone -q "$(source_of TEAR-ERC/tandem)" "$T/src"
  git -C "$T/src" checkout -q $TANDEM_COMMIT
  rm -rf "$T/src/submodules/mneme" "$T/src/submodules/yateto"
  git clone -q "$(source_of TEAR-ERC/mneme)" "$T/src/submodules/mneme"
  git -C "$T/src/submodules/mneme" checkout -q $MNEME_COMMIT
  git clone -q "$(source_of SeisSol/yateto)" "$T/src/submodules/yateto"
  git -C "$T/src/submodules/yateto" checkout -q $YATETO_COMMIT
fi
[ "$(git -C "$T/src" rev-parse HEAD)" = $TANDEM_COMMIT ] ||
  { echo "ERROR: $T/src is not at the pinned $TANDEM_COMMIT" >&2; exit 1; }
# our one patch (for Debian's PETSc 3.18; inert with 3.22): PetscStrcmpAny,
# PETSC_SUCCESS and PCReduceFailedReason spelled for 3.18; no physics
PATCH=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/petsc-3.18.patch
if [ -z "$(git -C "$T/src" diff --name-only)" ]; then git -C "$T/src" apply "$PATCH"
elif [ "$(git -C "$T/src" diff)" != "$(cat "$PATCH")" ]; then
  echo "ERROR: $T/src has changes other than $PATCH" >&2; exit 1
fi
ARCH=noarch; grep -q avx2 /proc/cpuinfo && ARCH=hsw
PKG_CONFIG_PATH=$PETSC/install/lib/pkgconfig \
cmake -S "$T/src" -B "$T/build-petsc322" -DCMAKE_BUILD_TYPE=Release -DDOMAIN_DIMENSION=2 \
  -DPOLYNOMIAL_DEGREE=4 -DARCH=$ARCH -DPython3_EXECUTABLE=/usr/bin/python3 -DCMAKE_PREFIX_PATH="$DEPS" \
  -DPARMETIS_INCLUDE_DIR="$DEPS/include" -DPARMETIS_LIBRARY="$DEPS/lib/libparmetis.so" \
  -DMETIS_INCLUDE_DIR="$DEPS/include" -DMETIS_LIBRARY="$DEPS/lib/libmetis.so" > "$T/cmake.log"
nice make -C "$T/build-petsc322" -j2 tandem > "$T/make.log" 2>&1 || { tail -20 "$T/make.log"; exit 1; }
echo "$T/build-petsc322/app/tandem"
