#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Independent peer run of SEAS BP6-QD-A / BP6-QD-S with HBI (github.com/sozawa94/hbi).
#
# usage: PEER_SRC=HBI_SRC benchmarks/seas-bp6/peer/run.sh OUTDIR [A|S|AS]
#   PEER_SRC   HBI checkout to use/create (required; not the BP4/BP5/BP7 ones). If absent it
#              is cloned from HBI_GIT (default: GitHub), checked out at the pinned commit and
#              patched with hbi-bp6-closedform.patch.
#   CELL       element size in m (default 10; must divide 500)
#   EPS        HBI eps_r, relative RK45 tolerance (default 1e-6)
#   DTMAX      max time step in s (default 3600; sets the station sampling)
#   NICE       nice level (default 10)
# Writes OUTDIR/<law>/{fltst_strk*.dat,global.dat,slip.dat,shear_stress.dat,timing.txt}
# and keeps HBI's native output in OUTDIR/<law>/native/.
set -euo pipefail

HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
PATCH=$HERE/hbi-bp6-closedform.patch
PY=/usr/bin/python3
[ -n "${PEER_SRC:-}" ] || { echo "$(basename "$0"): set PEER_SRC to the folder of HBI's checkout (cloned and patched there if absent)" >&2; exit 2; }
CELL=${CELL:-10}
EPS=${EPS:-1e-6}
DTMAX=${DTMAX:-3600}
NICE=${NICE:-10}
OUT=${1:?usage: PEER_SRC=DIR $0 OUTDIR [A|S|AS]}
LAWS=${2:-AS}

# ---------------------------------------------------------------- source + build (outside the repo)
source "$HERE/../../hbi-peer.sh"
hbi_checkout_and_build "$PEER_SRC" "$NICE" "$PATCH"
BIN=$HBI_BIN

# ---------------------------------------------------------------- geometry
# fault |x3| <= 20 km: NCELL = 40 km / CELL; HBI injects at cell NCELL/2 (1-based),
# so x3 = xcol - xcol(NCELL/2) runs from -20 km + CELL to +20 km (one extra cell on +x3).
NCELL=$(( 40000 / CELL ))
DS=$($PY -c "print($CELL/1000.0)")
IC=$(( NCELL / 2 ))

for LAW in $(echo "$LAWS" | grep -o .); do
  case $LAW in A) EV=aging ;; S) EV=slip ;; *) echo "law must be A or S" >&2; exit 1 ;; esac
  D=$OUT/$LAW; N=$D/native
  rm -rf "$N"; mkdir -p "$N"
  {
    echo "problem 2dp"            # 1D fault in a 2D whole space; kernel mu/(2 pi (1-nu)) ...
    echo "pois 0.0"               # ... with nu=0 -> mu/(2 pi) = antiplane
    echo "rigid 32.04"; echo "vs 3.464"   # GPa, km/s; radiation damping mu/(2 cs)
    echo "analyticalinjection T"; echo "pressurediffusion F"; echo "injection flowrate"
    echo "qinj 1.25e-6"           # m/s
    echo "tinj 0.273972602739726" # yr (= 100 days of 365-day years; t_off = 8640000 s)
    echo "kp 1e-13"; echo "eta 1e-3"; echo "beta 1e-8"; echo "phi 0.1"   # alpha = 0.1 m2/s
    echo "ncellg $NCELL"; echo "ds $DS"
    echo "filenumber 0"; echo "nstep 100000000"; echo "interval 100000000"
    echo "dtout 0.00273972602739726"     # field frames about every day (yr)
    echo "tmax 2.0"                      # yr (365 d) = 63072000 s
    echo "eps_r $EPS"; echo "dtmax $DTMAX"
    echo "a 0.007"; echo "b 0.005"; echo "dc 0.004"; echo "f0 0.60"; echo "vref 1e-6"
    echo "evlaw $EV"
    echo "tauinit 29.2"; echo "sigmainit 50.0"; echo "velinit 1d-12"
    echo "sr 0"; echo "vpl 0"; echo "backslip F"   # no tectonic loading
    for s in -1500 0 500 1000 1500 2500 3500 5000 7500; do echo "outloc $(( IC + s / CELL ))"; done
  } > "$N/bp6.in"
  echo "== BP6-QD-$LAW: HBI $HBI_COMMIT, cell ${CELL} m, eps_r $EPS, dtmax $DTMAX s -> $D"
  ( cd "$N" && OMP_NUM_THREADS=1 /usr/bin/time -v -o time.txt nice -n "$NICE" "$BIN" bp6.in > log.txt 2>&1 )
  grep -q "Time exceeds tmax" "$N/log.txt" || { echo "HBI did not reach tmax" >&2; tail "$N/log.txt"; exit 1; }
  nice -n "$NICE" $PY "$HERE/hbi2seas.py" "$N" "$D" --law "$LAW" --cell "$CELL" --commit "$HBI_COMMIT"
  {
    echo "code=HBI $HBI_COMMIT + $(basename "$PATCH")"
    echo "case=BP6-QD-$LAW cell=${CELL}m eps_r=$EPS dtmax=${DTMAX}s OMP_NUM_THREADS=1 MPI ranks=1 nice=$NICE"
    echo "steps=$(tail -1 "$N/output/monitor0.dat" | awk '{print $1}')"
    echo "host=$(hostname) nproc=$(nproc) loadavg_at_end=$(cut -d' ' -f1-3 /proc/loadavg)"
    grep -E "Elapsed|User time|System time|Maximum resident" "$N/time.txt"
  } > "$D/timing.txt"
  cat "$D/timing.txt"
done
