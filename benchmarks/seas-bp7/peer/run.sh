#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Independent peer run of SEAS BP7-QD (aging law) with HBI (github.com/sozawa94/hbi), problem 3dp (whole space).
# HBI is patched with ../../seas-bp5/peer/hbi-bp5.patch and then hbi-bp7.patch (the prescribed nucleation).
#
# usage: PEER_SRC=HBI_SRC benchmarks/seas-bp7/peer/run.sh OUTDIR
#   PEER_SRC   HBI checkout to use/create (required; NOT the BP4/BP5 one). If it is absent, it is
#              cloned from HBI_GIT (default: GitHub), checked out at the pinned commit and
#              patched with hbi-bp5.patch, then hbi-bp7.patch.
#   CELL       element size in m (default 10; must divide 800 into an even count)
#   EPS        HBI eps_r, relative RK45 tolerance (default 1e-6)
#   DTMAX      max time step in s (default 1e6)
#   TEND       end time in s (default 3.15576e8 = 10 yr of 365.25 d)
#   NUC        1 (default): input keyword `bp7nucleation T`; 0: no keyword (the patch is then inert)
#   NICE       nice level (default 10)
# Writes the SEAS files to OUTDIR (fltst_strk*.dat, global.dat, profiles, events.dat, timing.txt,
# summary.txt, check.txt) and keeps HBI's native output in OUTDIR/native/.
set -euo pipefail

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
PATCHES=("$HERE/../../seas-bp5/peer/hbi-bp5.patch" "$HERE/hbi-bp7.patch")
PY=/usr/bin/python3
[ -n "${PEER_SRC:-}" ] || { echo "$(basename "$0"): set PEER_SRC to the folder of HBI's checkout (cloned and patched there if absent)" >&2; exit 2; }
CELL=${CELL:-10}
EPS=${EPS:-1e-6}
DTMAX=${DTMAX:-1e6}
TEND=${TEND:-3.15576e8}
NUC=${NUC:-1}
NICE=${NICE:-10}
OUT=${1:?usage: PEER_SRC=DIR $0 OUTDIR}

# ---------------------------------------------------------------- source + build (outside the repo)
source "$HERE/../../hbi-peer.sh"
hbi_checkout_and_build "$PEER_SRC" "$NICE" "${PATCHES[@]}"
BIN=$HBI_BIN

# ---------------------------------------------------------------- input, run, convert
N=$OUT/native
rm -rf "$N"; mkdir -p "$N/output"
nucopt=""; [ "$NUC" = 1 ] || nucopt="--no-nucleation"
$PY "$HERE/bp7_input.py" "$N" --cell "$CELL" --eps "$EPS" --dtmax "$DTMAX" --tend "$TEND" $nucopt
echo "== BP7-QD: HBI $HBI_COMMIT + hbi-bp5.patch + hbi-bp7.patch (nucleation NUC=$NUC), problem 3dp," \
     "cell ${CELL} m, eps_r $EPS, dtmax $DTMAX s, t_end $TEND s -> $OUT"
# one MPI rank (HBI runs without mpirun as a singleton), one OpenMP thread
( cd "$N" && OMP_NUM_THREADS=1 /usr/bin/time -v -o time.txt nice -n "$NICE" "$BIN" bp7.in > log.txt 2>&1 )
grep -q "Time exceeds tmax" "$N/log.txt" || { echo "HBI did not reach tmax" >&2; tail "$N/log.txt"; exit 1; }
nice -n "$NICE" $PY "$HERE/hbi2seas_bp7.py" "$N" "$OUT" --commit "$HBI_COMMIT"
{
  echo "code=HBI $HBI_COMMIT + hbi-bp5.patch + hbi-bp7.patch"
  echo "case=BP7-QD-A problem=3dp cell=${CELL}m eps_r=$EPS dtmax=${DTMAX}s t_end=${TEND}s nucleation=$NUC OMP_NUM_THREADS=1 MPI ranks=1 nice=$NICE"
  echo "steps=$(tail -1 "$N/output/monitor0.dat" | awk '{print $1}')"
  echo "host=$(hostname) nproc=$(nproc) loadavg_at_end=$(cut -d' ' -f1-3 /proc/loadavg)"
  grep -E "Elapsed|User time|System time|Maximum resident" "$N/time.txt"
} > "$OUT/timing.txt"
cat "$OUT/timing.txt"
$PY "$HERE/bp7_summary.py" "$OUT" | tee "$OUT/summary.txt"
$PY "$HERE/bp7_check.py" "$N" | tee "$OUT/check.txt"
