#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Independent peer run of SEAS BP4-QD with HBI (github.com/sozawa94/hbi), problem 3dp (whole space).
# It uses the HBI build and patch of the BP5 peer run (../../seas-bp5/peer/hbi-bp5.patch).
#
# usage: PEER_SRC=HBI_SRC benchmarks/seas-bp4/peer/run.sh OUTDIR
#   PEER_SRC   HBI checkout to use/create (required; the BP5 one serves). If it is absent, it is
#              cloned from HBI_GIT (default: GitHub), checked out at the pinned commit and
#              patched with hbi-bp5.patch.
#   CELL       element size in km (default 1; must divide 100 and 80 into even counts)
#   EPS        HBI eps_r, relative RK45 tolerance (default 1e-6)
#   DTMAX      max time step in s (default 3155760 = 0.1 yr of 365.25 d)
#   TEND       end time in s (default 3.15576e10 = 1000 yr of 365.25 d, as prm/seas-bp4-qd.prm)
#   NICE       nice level (default 10)
# Writes the SEAS files to OUTDIR (fltst_strk*.dat, global.dat, profiles, events.dat, timing.txt,
# summary.txt) and keeps HBI's native output in OUTDIR/native/.
set -euo pipefail

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
BP5=$HERE/../../seas-bp5/peer
PATCH=$BP5/hbi-bp5.patch
PY=/usr/bin/python3
[ -n "${PEER_SRC:-}" ] || { echo "$(basename "$0"): set PEER_SRC to the folder of HBI's checkout (cloned and patched there if absent)" >&2; exit 2; }
CELL=${CELL:-1}
EPS=${EPS:-1e-6}
DTMAX=${DTMAX:-3155760}
TEND=${TEND:-3.15576e10}
NICE=${NICE:-10}
OUT=${1:?usage: PEER_SRC=DIR $0 OUTDIR}

# ---------------------------------------------------------------- source + build (outside the repo)
source "$HERE/../../hbi-peer.sh"
hbi_checkout_and_build "$PEER_SRC" "$NICE" "$PATCH"
BIN=$HBI_BIN

# ---------------------------------------------------------------- input, run, convert
N=$OUT/native
rm -rf "$N"; mkdir -p "$N"
$PY "$HERE/bp4_input.py" "$N" --cell "$CELL" --eps "$EPS" --dtmax "$DTMAX" --tend "$TEND"
echo "== BP4-QD: HBI $HBI_COMMIT + hbi-bp5.patch, problem 3dp, cell ${CELL} km, eps_r $EPS, dtmax $DTMAX s, t_end $TEND s -> $OUT"
# one MPI rank (HBI runs without mpirun as a singleton), one OpenMP thread
( cd "$N" && OMP_NUM_THREADS=1 /usr/bin/time -v -o time.txt nice -n "$NICE" "$BIN" bp4.in > log.txt 2>&1 )
grep -q "Time exceeds tmax" "$N/log.txt" || { echo "HBI did not reach tmax" >&2; tail "$N/log.txt"; exit 1; }
nice -n "$NICE" $PY "$HERE/hbi2seas_bp4.py" "$N" "$OUT" --commit "$HBI_COMMIT"
{
  echo "code=HBI $HBI_COMMIT + hbi-bp5.patch"
  echo "case=BP4-QD problem=3dp cell=${CELL}km eps_r=$EPS dtmax=${DTMAX}s t_end=${TEND}s OMP_NUM_THREADS=1 MPI ranks=1 nice=$NICE"
  echo "steps=$(tail -1 "$N/output/monitor0.dat" | awk '{print $1}')"
  echo "host=$(hostname) nproc=$(nproc) loadavg_at_end=$(cut -d' ' -f1-3 /proc/loadavg)"
  grep -E "Elapsed|User time|System time|Maximum resident" "$N/time.txt"
} > "$OUT/timing.txt"
cat "$OUT/timing.txt"
$PY "$BP5/bp5_summary.py" "$OUT" --yr 365.25 | tee "$OUT/summary.txt"
