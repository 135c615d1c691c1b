#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Independent peer run of SEAS BP3-QD (a dipping thrust or normal fault, half-space, slip-induced
# normal-stress changes) with HBI (github.com/sozawa94/hbi).
#
# usage: PEER_SRC=HBI_SRC benchmarks/seas-bp3/peer/run.sh OUTDIR
#   PEER_SRC   HBI checkout to use/create (required). If absent it is cloned (from HBI_GIT, else
#              GitHub: ../../hbi-peer.sh), checked out at the pinned commit and patched with
#              ../../seas-bp5/peer/hbi-bp5.patch.
#   CELL       element size in m (default 25; must divide 2500)
#   EPS        HBI eps_r, relative RK45 tolerance (default 1e-6)
#   STIFFEN    the kernels F times stiffer, the damping unchanged (default 1: the benchmark;
#              a sensitivity study, bp3_input.py --stiffen)
#   DTMAX      max time step in s (default 3153600 = 0.1 yr of 365 d; interseismic sampling)
#   TMAX       end time in years of 365 d (default 1500)
#   NICE       nice level (default 10)
#   DIP        the fault's dip in degrees (default 60; BP3 also runs 30 and 90)
#   SIGMACONST 1: HBI's sigmaconst (the slip does not change the normal stress; a diagnostic, not
#              BP3; rsfcycle's counterpart: git show a644040:benchmarks/seas-bp3/freeze-normal.patch)
#   SENSE      thrust (default) or normal: BP3's normal-faulting variant, V_p = V_init = -1e-9 m/s and
#              prestress -tau0; outputs stay thrust-positive (slip, shear stress negative)
# Writes OUTDIR/{fltst_dpXXX.dat,global.dat,events.txt,srfst_x[+-]8.dat,timing.txt} and keeps HBI's native
# output in OUTDIR/native/. HBI runs on one MPI rank (mpirun -np 1), OMP_NUM_THREADS=1.
set -euo pipefail

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# the BP5 peer patch (no physics: an out-of-bounds fix, 64 stations, full-precision output)
PATCH=$HERE/../../seas-bp5/peer/hbi-bp5.patch
PY=/usr/bin/python3
[ -n "${PEER_SRC:-}" ] || { echo "usage: PEER_SRC=HBI_SRC $0 OUTDIR (PEER_SRC: HBI's checkout, cloned there if absent)" >&2; exit 2; }
CELL=${CELL:-25}
EPS=${EPS:-1e-6}
DTMAX=${DTMAX:-3153600}
TMAX=${TMAX:-1500}
NICE=${NICE:-10}
SENSE=${SENSE:-thrust}
DIP=${DIP:-60}
STIFFEN=${STIFFEN:-1}
case $SENSE in thrust|normal) ;; *) echo "SENSE must be thrust or normal" >&2; exit 2;; esac
OUT=${1:?usage: PEER_SRC=DIR $0 OUTDIR}

# ---------------------------------------------------------------- source + build (outside the repo)
source "$HERE/../../hbi-peer.sh"
hbi_checkout_and_build "$PEER_SRC" "$NICE" "$PATCH"
BIN=$HBI_BIN

# ---------------------------------------------------------------- input, run, convert
N=$OUT/native
rm -rf "$N"; mkdir -p "$N"
$PY "$HERE/bp3_input.py" "$N" --cell "$CELL" --eps "$EPS" --dtmax "$DTMAX" --tmax "$TMAX" --sense "$SENSE" --dip "$DIP" --stiffen "$STIFFEN"
if [ "${SIGMACONST:-0}" = 1 ]; then echo "sigmaconst T" >> "$N/bp3.in"; fi
echo "== BP3-QD (dip $DIP, $SENSE): HBI $HBI_COMMIT + $(basename "$PATCH"), cell ${CELL} m, eps_r $EPS, dtmax $DTMAX s, tmax $TMAX yr -> $OUT"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
( cd "$N" && /usr/bin/time -v -o time.txt nice -n "$NICE" mpirun -np 1 "$BIN" bp3.in > log.txt 2>&1 ) || true
grep -q "Time exceeds tmax" "$N/log.txt" || { echo "WARNING: HBI did not reach tmax" >&2; tail -3 "$N/log.txt" >&2; }
nice -n "$NICE" $PY "$HERE/hbi2seas_bp3.py" "$N" "$OUT" --commit "$HBI_COMMIT"
# surface displacement at x = +-8 km (post-processed from HBI slip frames; HBI does not compute it)
nice -n "$NICE" $PY "$HERE/hbi_surface_bp3.py" "$N" "$OUT" --dip "$DIP"
{
  echo "code=HBI $HBI_COMMIT + $(basename "$PATCH")"
  echo "case=BP3-QD dip $DIP $SENSE, stiffen=$STIFFEN, sigmaconst=${SIGMACONST:-0}, cell=${CELL}m eps_r=$EPS dtmax=${DTMAX}s tmax=${TMAX}yr(365d) OMP_NUM_THREADS=1 MPI ranks=1 nice=$NICE"
  echo "steps=$(tail -1 "$N/output/monitor0.dat" | awk '{print $1}')"
  echo "host=$(hostname) nproc=$(nproc --all) loadavg_at_end=$(cut -d' ' -f1-3 /proc/loadavg) (machine shared: one core busy with another computation)"
  grep -E "Elapsed|User time|System time|Maximum resident" "$N/time.txt"
} > "$OUT/timing.txt"
cat "$OUT/timing.txt"
