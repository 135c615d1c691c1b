#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Third code for SEAS BP3-QD: tandem (github.com/TEAR-ERC/tandem;
# discontinuous Galerkin, finite box, discrete Green's functions).
#
# usage: TANDEM_PREFIX=PREFIX benchmarks/seas-bp3/tandem/run.sh OUTDIR
#   LF     fault element size in km (default 0.1: degree-4 elements, so 5
#          nodes per 100 m of fault; tandem's own default is 0.02)
#   DIP    30, 60 (default) or 90
#   SENSE  thrust (default) or normal
#   RTOL   the Runge-Kutta's tolerance, -ts_atol of tandem's rk45.cfg
#          (default 1e-7, as that file; it is absolute on slip and state)
#   TMAX   end time in years of 365 days (default 1500)
#   NICE   nice level (default 10)
#   TANDEM_PREFIX  where build.sh puts tandem (required; built there if absent)
#   RESUME 1: continue OUTDIR's run from its last time-loop checkpoint
#          (OUTDIR/checkpoint, written every 10 CPU minutes; the Green's
#          functions are read from OUTDIR/gf). The same LF, DIP and SENSE
#          as the first run; tandem appends to its output files, and
#          the conversion keeps the restarted rows where the times overlap.
# Builds tandem if absent (build.sh), meshes tandem's bp3.geo with gmsh,
# writes OUTDIR/bp3.toml, runs it on one rank with PETSc's own LU (nested
# dissection; the PETSc of build.sh has no MUMPS) for the Green's functions
# and RK45 (Dormand-Prince), and converts the output to BP3's files
# (fltst_dpXXX, srfst_fn+08, srfst_fn-08, global.dat) with the package
# module rsfcycle.peers.tandem (python/ of this repository), which
# `benchmarks/seas-bp3/run.py tables` reads beside rsfcycle's and HBI's.
# benchmarks/seas-bp3/run.py tandem OUTDIR runs this script.
set -euo pipefail
case "${1:-}" in -h|--help) sed -n '3,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0;; esac
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
ROOT=$(cd "$HERE/../../.." && pwd)
# the package rsfcycle of this repository
py() { PYTHONPATH="$ROOT/python${PYTHONPATH:+:$PYTHONPATH}" /usr/bin/python3 "$@"; }
LF=${LF:-0.1}
DIP=${DIP:-60}
SENSE=${SENSE:-thrust}
RTOL=${RTOL:-1e-7}
TMAX=${TMAX:-1500}
NICE=${NICE:-10}
[ -n "${TANDEM_PREFIX:-}" ] || { echo "usage: TANDEM_PREFIX=PREFIX $0 OUTDIR (PREFIX: where build.sh puts tandem)" >&2; exit 2; }
PEERS=$TANDEM_PREFIX
OUT=${1:?usage: TANDEM_PREFIX=PREFIX $0 OUTDIR}
BIN=$PEERS/tandem/build-petsc322/app/tandem
[ -x "$BIN" ] || "$HERE/build.sh" "$PEERS"
SRC=$PEERS/tandem/src/examples/tandem/2d

MESH=bp3-d$DIP-Lf$LF.msh
RESUME_FLAG=()
if [ "${RESUME:-0}" = 1 ]; then
  for f in "$OUT/$MESH" "$OUT/checkpoint/last_checkpoint.txt"; do
    [ -f "$f" ] || { echo "RESUME=1: $f is missing (LF, DIP and SENSE as the first run?)" >&2; exit 2; }
  done
  RESUME_FLAG=(--resume)
else
  mkdir -p "$OUT"
  rm -f "$OUT/log.txt" "$OUT/time.txt"
  cp "$SRC/bp3.lua" "$SRC/bp3.geo" "$OUT/"
  (cd "$OUT" && gmsh -2 -setnumber Lf "$LF" -setnumber Ls "$LF" -setnumber dip "$DIP" bp3.geo \
     -o "$MESH" > gmsh.log 2>&1)
fi
py -m rsfcycle.peers.tandem input "$OUT" --dip "$DIP" --sense "$SENSE" --mesh "$MESH" \
  --final-time "$(py -c "print($TMAX * 3.1536e7)")" "${RESUME_FLAG[@]}" > /dev/null
VERSION=$(git -C "$PEERS/tandem/src" rev-parse --short HEAD)
echo "== BP3-QD (dip $DIP, $SENSE): tandem $VERSION, Lf $LF km, degree 4, RK atol $RTOL, $TMAX yr -> $OUT"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
# GKlib, METIS, ParMETIS and PETSc 3.22 (build.sh)
export LD_LIBRARY_PATH=$PEERS/tandem-deps/lib:$PEERS/petsc/install/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
( cd "$OUT" && /usr/bin/time -v -a -o time.txt nice -n "$NICE" mpirun -np 1 "$BIN" bp3.toml --petsc \
    -ksp_type preonly -pc_type lu -pc_factor_mat_ordering_type nd \
    -ts_type rk -ts_rk_type 5dp -ts_rtol 1e-50 -ts_atol "$RTOL" -ts_adapt_wnormtype infinity \
    >> log.txt 2>&1 )
py -m rsfcycle.peers.tandem convert "$OUT" --version "$VERSION" --element-size "$LF km elements of degree 4"
