#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# The peer run of SEAS BP1-FD with SCycle (README.md in this folder);
# benchmarks/seas-bp1/run.py peers calls it.
#
# Usage (from the repository's root):
#   PYTHONPATH=python SCYCLE_SRC=DIR benchmarks/seas-bp1/scycle/run.sh OUTDIR
#       [input options]
#
# DIR: a git clone of https://github.com/kali-allison/SCycle. If its HEAD is
# not the pinned commit, it is checked out at it (detached HEAD; refused if
# the clone has local changes); scycle.patch (next to this script) is then
# applied and source/main is built with Debian's PETSc:
#   make PETSC_DIR=/usr/lib/petsc CLINKER=mpicxx CXXFLAGS="-DVERBOSE=1 -std=c++14 -Wall -g" main
# (VERBOSE=1 prints one line per time step, which the statistics read). The
# build needs the Debian packages petsc-dev and libopenmpi-dev; the input
# and the statistics (python3 -m rsfcycle.peers.scycle input|stats) need
# python3-numpy, python3-pandas and python3-h5py; the timing needs the
# package time. This script installs nothing.
#
# Runs one process on one core (no mpirun: MPI starts as a singleton;
# OMP_NUM_THREADS=OPENBLAS_NUM_THREADS=1) in OUTDIR: bp1fd.in and ICs/ from
# `rsfcycle.peers.scycle input` (defaults: the 50 m run, three events; the
# input options, e.g. --h 0.1 --trigger-qd2fd 1e-4, change them), SCycle's
# output in OUTDIR/output, its screen output in log.txt, /usr/bin/time -v
# in time.txt, the event table in events.md, the series in series.csv and
# SEAS-style files (fltst_dpXXX, devol.dat) in OUTDIR/seas.
#
# PETSC_OPTIONS gets -mat_mumps_icntl_14 100 (+100 % MUMPS workspace: without
# it the 50 m factorisation fails silently and SCycle stops on a stress of
# -4e286) and -mat_mumps_icntl_4 1 (MUMPS errors in the log). If OPENBLAS_LIB
# names a folder with a serial OpenBLAS libblas.so.3 (e.g. unpacked from the
# Debian package libopenblas0-serial with dpkg -x), it is put first in
# LD_LIBRARY_PATH: MUMPS factorises 4x faster; the solves do not change.
set -euo pipefail

SCYCLE_COMMIT=74a132f6d280f550dd7469faa7b1039a52b24156
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../../.." && pwd)
PYTHON=${PYTHON:-/usr/bin/python3}

# die, help_if_asked
. "$ROOT/python/rsfcycle/bench.sh"

[ $# -ge 1 ] || die "usage: SCYCLE_SRC=DIR run.sh OUTDIR [input options]"
help_if_asked "$1"
outdir=$1
shift
[ -n "${SCYCLE_SRC:-}" ] || die "set SCYCLE_SRC to a clone of https://github.com/kali-allison/SCycle"
[ -f "$SCYCLE_SRC/source/Makefile" ] || die "$SCYCLE_SRC is not an SCycle clone (no source/Makefile)"
[ -x /usr/bin/time ] || die "/usr/bin/time not found (Debian package time)"
"$PYTHON" -c "import rsfcycle.peers.scycle" 2> /dev/null ||
    die "$PYTHON cannot import rsfcycle: run from the repository's root with PYTHONPATH=python"
"$PYTHON" -c "import h5py, numpy" 2> /dev/null ||
    die "$PYTHON cannot import h5py and numpy (the statistics need them): apt-get install -y python3-h5py python3-numpy"
[ ! -e "$outdir/log.txt" ] || die "$outdir has a run already (log.txt)"
SCYCLE_SRC=$(cd "$SCYCLE_SRC" && pwd)

# --- SCycle at the pinned commit, with scycle.patch
head=$(git -C "$SCYCLE_SRC" rev-parse HEAD)
exe=$SCYCLE_SRC/source/main
if [ "$head" != "$SCYCLE_COMMIT" ]; then
    [ -z "$(git -C "$SCYCLE_SRC" status --porcelain --untracked-files=no)" ] ||
        die "$SCYCLE_SRC has local changes; not checking out $SCYCLE_COMMIT"
    echo "checking out SCycle $SCYCLE_COMMIT in $SCYCLE_SRC (was $head)"
    git -C "$SCYCLE_SRC" checkout --quiet "$SCYCLE_COMMIT"
    rm -f "$exe"
fi
if git -C "$SCYCLE_SRC" apply --check "$HERE/scycle.patch" 2> /dev/null; then
    echo "applying scycle.patch"
    git -C "$SCYCLE_SRC" apply "$HERE/scycle.patch"
    rm -f "$exe"
elif ! git -C "$SCYCLE_SRC" apply --check --reverse "$HERE/scycle.patch" 2> /dev/null; then
    die "scycle.patch neither applies to nor is applied in $SCYCLE_SRC"
fi
mkdir -p "$outdir"
outdir=$(cd "$outdir" && pwd)
if [ ! -x "$exe" ]; then
    [ -d /usr/lib/petsc ] || die "/usr/lib/petsc not found: install the Debian package petsc-dev"
    echo "building SCycle in $SCYCLE_SRC/source (log: $outdir/build.log)"
    make -C "$SCYCLE_SRC/source" PETSC_DIR=/usr/lib/petsc CLINKER=mpicxx \
        CXXFLAGS="-DVERBOSE=1 -std=c++14 -Wall -g" main > "$outdir/build.log" 2>&1 ||
        die "the build failed, see $outdir/build.log"
fi
echo "SCycle $(git -C "$SCYCLE_SRC" rev-parse HEAD) + scycle.patch: $exe"

# --- the run
"$PYTHON" -m rsfcycle.peers.scycle input "$outdir" "$@" > "$outdir/gen.txt"
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
export PETSC_OPTIONS="-mat_mumps_icntl_14 100 -mat_mumps_icntl_4 1"
if [ -n "${OPENBLAS_LIB:-}" ]; then
    export LD_LIBRARY_PATH=$OPENBLAS_LIB${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
fi
echo "start $(date -Is)" | tee "$outdir/timing.txt"
(cd "$outdir" && /usr/bin/time -v "$exe" bp1fd.in > log.txt 2> time.txt) ||
    die "SCycle failed in $outdir (log.txt, time.txt there)"
echo "end   $(date -Is)" | tee -a "$outdir/timing.txt"
grep -E "Elapsed|User time|Maximum resident" "$outdir/time.txt"
"$PYTHON" -m rsfcycle.peers.scycle stats "$outdir" --csv "$outdir/series.csv" \
    --seas "$outdir/seas" | tee "$outdir/events.md"
