#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Independent peer run of SEAS BP5-QD with HBI (github.com/sozawa94/hbi).
#
# usage: PEER_SRC=HBI_SRC benchmarks/seas-bp5/peer/run.sh OUTDIR
#   PEER_SRC   HBI checkout to use/create (required). If it is absent, it is cloned from
#              HBI_GIT (default: GitHub), checked out at the pinned commit and patched with
#              hbi-bp5.patch.
#   CELL       element size in km (default 1, the official BP5 size; must divide 100 and 40)
#   EPS        HBI eps_r, relative RK45 tolerance (default 1e-6)
#   DTMAX      max time step in s (default 3153600 = 0.1 yr of 365 d; sets the interseismic sampling)
#   TMAX       end time in years of 365 d (default 1800 = 56764800000 s)
#   NICE       nice level (default 10)
#   STIFFEN    the kernel F times stiffer, the damping unchanged (default 1: the benchmark;
#              a sensitivity study, bp5_input.py --stiffen)
#   PARAM_FILE optional: replace the generated bp5_param.dat (a dc tau vel per cell) by this file,
#              e.g. $PEER_SRC/examples/bp5r_param.dat (HBI's shipped BP5 parameters, CELL=1 only)
# Writes the SEAS files to OUTDIR (fltst_strk*.dat, global.dat, profiles, events.dat, timing.txt)
# and keeps HBI's native output in OUTDIR/native/.
set -euo pipefail

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
PATCH=$HERE/hbi-bp5.patch
PY=/usr/bin/python3
[ -n "${PEER_SRC:-}" ] || { echo "$(basename "$0"): set PEER_SRC to the folder of HBI's checkout (cloned and patched there if absent)" >&2; exit 2; }
CELL=${CELL:-1}
EPS=${EPS:-1e-6}
DTMAX=${DTMAX:-3153600}
TMAX=${TMAX:-1800}
NICE=${NICE:-10}
STIFFEN=${STIFFEN:-1}
OUT=${1:?usage: PEER_SRC=DIR $0 OUTDIR}

# ---------------------------------------------------------------- source + build (outside the repo)
source "$HERE/../../hbi-peer.sh"
hbi_checkout_and_build "$PEER_SRC" "$NICE" "$PATCH"
BIN=$HBI_BIN

# ---------------------------------------------------------------- input, run, convert
N=$OUT/native
rm -rf "$N"; mkdir -p "$N"
$PY "$HERE/bp5_input.py" "$N" --cell "$CELL" --eps "$EPS" --dtmax "$DTMAX" --tmax "$TMAX" --stiffen "$STIFFEN"
if [ -n "${PARAM_FILE:-}" ]; then
  [ "$(($(wc -l < "$PARAM_FILE")))" -eq "$(($(wc -l < "$N/bp5_param.dat")))" ] || { echo "PARAM_FILE has the wrong cell count" >&2; exit 1; }
  cp "$PARAM_FILE" "$N/bp5_param.dat"; echo "parameters from $PARAM_FILE"
fi
echo "== BP5-QD: HBI $HBI_COMMIT + $(basename "$PATCH"), cell ${CELL} km, eps_r $EPS, dtmax $DTMAX s, tmax $TMAX yr -> $OUT"
# one MPI rank (HBI runs without mpirun as a singleton), one OpenMP thread
( cd "$N" && OMP_NUM_THREADS=1 /usr/bin/time -v -o time.txt nice -n "$NICE" "$BIN" bp5.in > log.txt 2>&1 )
grep -q "Time exceeds tmax" "$N/log.txt" || { echo "HBI did not reach tmax" >&2; tail "$N/log.txt"; exit 1; }
nice -n "$NICE" $PY "$HERE/hbi2seas.py" "$N" "$OUT" --commit "$HBI_COMMIT"
{
  echo "code=HBI $HBI_COMMIT + $(basename "$PATCH")"
  [ -n "${PARAM_FILE:-}" ] && echo "parameter file: $PARAM_FILE"
  echo "case=BP5-QD stiffen=$STIFFEN cell=${CELL}km eps_r=$EPS dtmax=${DTMAX}s tmax=${TMAX}yr(365d) OMP_NUM_THREADS=1 MPI ranks=1 nice=$NICE"
  echo "steps=$(tail -1 "$N/output/monitor0.dat" | awk '{print $1}')"
  echo "host=$(hostname) nproc=$(nproc) loadavg_at_end=$(cut -d' ' -f1-3 /proc/loadavg)"
  grep -E "Elapsed|User time|System time|Maximum resident" "$N/time.txt"
} > "$OUT/timing.txt"
cat "$OUT/timing.txt"
$PY "$HERE/bp5_summary.py" "$OUT" | tee "$OUT/summary.txt"
