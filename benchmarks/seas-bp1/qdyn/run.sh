#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# The peer run of SEAS BP1-QD with QDYN (README.md in this folder).
#
# Usage:
#   QDYN_SRC=DIR benchmarks/seas-bp1/qdyn/run.sh OUTDIR [--bp2 | --bp2-only]
#                                                [--tmax YEARS] [--n N]
#
# DIR: a git clone of https://github.com/ydluo/qdyn. If its HEAD is not the
# pinned commit, a clean clone is checked out at it (detached HEAD) and
# rebuilt; if src/qdyn is missing it is built, in src/ with
#   make F90=mpif90 OPT="-O3"
# (the MPI wrapper is needed because parallel.f90 uses the module mpi). The
# build needs the Debian packages gfortran and libopenmpi-dev; make_input.py
# and stats.py need python3-numpy and python3-pandas; the timing needs the
# package time (/usr/bin/time). This script installs nothing.
#
# Runs, one after the other, as one process on one core (no mpirun: MPI
# starts as a singleton; OMP_NUM_THREADS=1):
#   OUTDIR/A_L40_N2048    BP1-QD run A: L = 40 km, N = 2048 (19.53 m),
#                         ACC = 1e-8, 3000 years
#   OUTDIR/BP2_L40_N2048  with --bp2 or --bp2-only: the same with
#                         D_c = 4 mm, 1200 years
# --tmax YEARS ends both at YEARS instead (a test); --n N takes N elements
# instead of 2048 (a power of 2: 4096 gives 9.77 m; the names say N).
# Each folder gets qdyn.in, iot_depths.txt, QDYN's output, log.txt (QDYN's
# screen output) and time.txt (/usr/bin/time -v). OUTDIR gets NAME.gen.txt
# (make_input.py's output), timing.txt (start and end dates),
# stats_NAME.md and stats_NAME_events.csv (the event table) and
# NAME_series.csv (the thinned series for compare.py and cycles.py).
set -euo pipefail

QDYN_COMMIT=e06edb1db4d402fbc4581e086a019d30e433cc56
HERE=$(cd "$(dirname "$0")" && pwd)
PYTHON=${PYTHON:-/usr/bin/python3}

# die
. "$HERE/../../common.sh"

outdir=
cases="A"
tmax=
n=2048
while [ $# -gt 0 ]; do
    case $1 in
        --bp2) cases="A BP2" ;;
        --bp2-only) cases="BP2" ;;
        --tmax)
            [ $# -ge 2 ] || die "--tmax needs a number of years"
            tmax=$2
            shift
            ;;
        --n)
            [ $# -ge 2 ] || die "--n needs a number of elements"
            n=$2
            shift
            ;;
        -h | --help)
            sed -n '2,/^set -e/p' "$0" | sed '$d; s/^# \{0,1\}//'
            exit 0
            ;;
        -*) die "unknown option $1" ;;
        *)
            [ -z "$outdir" ] || die "one OUTDIR only"
            outdir=$1
            ;;
    esac
    shift
done
[ -n "$outdir" ] || die "usage: QDYN_SRC=DIR run.sh OUTDIR [--bp2 | --bp2-only] [--tmax YEARS]"
[ -n "${QDYN_SRC:-}" ] || die "set QDYN_SRC to a clone of https://github.com/ydluo/qdyn"
if [ ! -f "$QDYN_SRC/src/Makefile" ] || [ ! -f "$QDYN_SRC/src/pyqdyn.py" ]; then
    die "$QDYN_SRC is not a QDYN clone (no src/Makefile, src/pyqdyn.py)"
fi
[ -x /usr/bin/time ] || die "/usr/bin/time not found (Debian package time)"
QDYN_SRC=$(cd "$QDYN_SRC" && pwd)
mkdir -p "$outdir"
outdir=$(cd "$outdir" && pwd)

# --- QDYN at the pinned commit
rebuild=0
head=$(git -C "$QDYN_SRC" rev-parse HEAD)
if [ "$head" != "$QDYN_COMMIT" ]; then
    [ -z "$(git -C "$QDYN_SRC" status --porcelain --untracked-files=no)" ] ||
        die "$QDYN_SRC has local changes; not checking out $QDYN_COMMIT"
    echo "checking out QDYN $QDYN_COMMIT in $QDYN_SRC (was $head)"
    git -C "$QDYN_SRC" checkout --quiet "$QDYN_COMMIT"
    rebuild=1
fi
exe=$QDYN_SRC/src/qdyn
if [ $rebuild = 1 ] || [ ! -x "$exe" ]; then
    command -v mpif90 > /dev/null ||
        die "mpif90 not found: install the Debian packages gfortran and libopenmpi-dev"
    echo "building QDYN in $QDYN_SRC/src (log: $outdir/build.log)"
    if [ $rebuild = 1 ]; then
        make -C "$QDYN_SRC/src" clean > "$outdir/build.log" 2>&1
    fi
    make -C "$QDYN_SRC/src" F90=mpif90 OPT="-O3" >> "$outdir/build.log" 2>&1 ||
        die "the build failed, see $outdir/build.log"
fi
echo "QDYN $(git -C "$QDYN_SRC" rev-parse HEAD): $exe"

# --- the runs
export OMP_NUM_THREADS=1

run_case() {  # name, stats.py options, make_input.py options ...
    local name=$1 stats_options=$2
    shift 2
    local dir=$outdir/$name
    [ ! -e "$dir/output_vmax" ] || die "$dir has QDYN output already"
    "$PYTHON" "$HERE/make_input.py" --qdyn-src "$QDYN_SRC" "$dir" "$@" \
        ${tmax:+--tmax_yr "$tmax"} > "$outdir/$name.gen.txt"
    echo "start $name $(date -Is)" | tee -a "$outdir/timing.txt"
    (cd "$dir" && /usr/bin/time -v "$exe" > log.txt 2> time.txt) ||
        die "QDYN failed in $dir (log.txt, time.txt there)"
    echo "end   $name $(date -Is)" | tee -a "$outdir/timing.txt"
    grep -E "Elapsed|User time|System time" "$dir/time.txt"
    # shellcheck disable=SC2086  # stats_options is a list of words
    "$PYTHON" "$HERE/stats.py" "$dir" --md "$outdir/stats_$name.md" \
        --csv "$outdir/${name}_series.csv" $stats_options
}

for c in $cases; do
    case $c in
        A) run_case "A_L40_N$n" "--regular_from_event 5" \
            --L 40e3 --N "$n" --acc 1e-8 --tmax_yr 3000 ;;
        BP2) run_case "BP2_L40_N$n" "" \
            --L 40e3 --N "$n" --acc 1e-8 --tmax_yr 1200 --Dc 4e-3 ;;
    esac
done
