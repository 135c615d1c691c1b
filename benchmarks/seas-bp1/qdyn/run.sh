#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# The peer runs of SEAS BP1-QD and BP2-QD with QDYN (README.md in this
# folder); benchmarks/seas-bp1/run.py peers calls it.
#
# Usage (from the repository's root):
#   PYTHONPATH=python QDYN_SRC=DIR benchmarks/seas-bp1/qdyn/run.sh OUTDIR
#       [--bp2 | --bp2-only] [--tmax YEARS] [--n N] [--acc ACC]
#
# DIR: a git clone of https://github.com/ydluo/qdyn. If its HEAD is not the
# pinned commit, a clean clone is checked out at it (detached HEAD) and
# rebuilt; if src/qdyn is missing it is built, in src/ with
#   make F90=mpif90 OPT="-O3"
# (the MPI wrapper is needed because parallel.f90 uses the module mpi). The
# build needs the Debian packages gfortran and libopenmpi-dev; the input
# and the statistics (python3 -m rsfcycle.peers.qdyn input|stats) need
# python3-numpy and python3-pandas; the timing needs the package time
# (/usr/bin/time). This script installs nothing.
#
# Runs, one after the other, as one process on one core (no mpirun: MPI
# starts as a singleton; OMP_NUM_THREADS=1):
#   OUTDIR/A_L40_N2048    BP1-QD: L = 40 km, N = 2048 (19.53 m),
#                         ACC = 1e-8, 3000 years
#   OUTDIR/BP2_L40_N2048  with --bp2 or --bp2-only: the same with
#                         D_c = 4 mm, 1200 years
# --tmax YEARS ends both at YEARS instead (a test); --n N takes N elements
# instead of 2048 (a power of 2: 1024 gives 39.06 m, 4096 9.77 m; the
# names say N); --acc ACC takes QDYN's ACC instead of 1e-8 (the names end
# in _ACC<ACC>). Each folder gets qdyn.in, iot_depths.txt, QDYN's output,
# log.txt (QDYN's screen output) and time.txt (/usr/bin/time -v). OUTDIR
# gets NAME.gen.txt (the input's summary), timing.txt (start and end
# dates), stats_NAME.md and stats_NAME_events.csv (the event table) and
# NAME_series.csv (the thinned series run.py reads).
set -euo pipefail

QDYN_COMMIT=e06edb1db4d402fbc4581e086a019d30e433cc56
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../../.." && pwd)
PYTHON=${PYTHON:-/usr/bin/python3}

# die, help_if_asked
. "$ROOT/python/rsfcycle/bench.sh"

outdir=
cases="A"
tmax=
n=2048
acc=1e-8
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
        --acc)
            [ $# -ge 2 ] || die "--acc needs QDYN's ACC"
            acc=$2
            shift
            ;;
        -h | --help) help_if_asked "$1" ;;
        -*) die "unknown option $1" ;;
        *)
            [ -z "$outdir" ] || die "one OUTDIR only"
            outdir=$1
            ;;
    esac
    shift
done
[ -n "$outdir" ] || die "usage: QDYN_SRC=DIR run.sh OUTDIR [--bp2 | --bp2-only] [--tmax YEARS] [--n N] [--acc ACC]"
[ -n "${QDYN_SRC:-}" ] || die "set QDYN_SRC to a clone of https://github.com/ydluo/qdyn"
"$PYTHON" -c "import rsfcycle.peers.qdyn" 2> /dev/null ||
    die "$PYTHON cannot import rsfcycle: run from the repository's root with PYTHONPATH=python"
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

run_case() {  # name, stats options, input options ...
    local name=$1 stats_options=$2
    shift 2
    local dir=$outdir/$name
    [ ! -e "$dir/output_vmax" ] || die "$dir has QDYN output already"
    "$PYTHON" -m rsfcycle.peers.qdyn input --qdyn-src "$QDYN_SRC" "$dir" "$@" \
        ${tmax:+--tmax-yr "$tmax"} > "$outdir/$name.gen.txt"
    echo "start $name $(date -Is)" | tee -a "$outdir/timing.txt"
    (cd "$dir" && /usr/bin/time -v "$exe" > log.txt 2> time.txt) ||
        die "QDYN failed in $dir (log.txt, time.txt there)"
    echo "end   $name $(date -Is)" | tee -a "$outdir/timing.txt"
    grep -E "Elapsed|User time|System time" "$dir/time.txt"
    # shellcheck disable=SC2086  # stats_options is a list of words
    "$PYTHON" -m rsfcycle.peers.qdyn stats "$dir" --md "$outdir/stats_$name.md" \
        --csv "$outdir/${name}_series.csv" $stats_options
}

suffix=
[ "$acc" = 1e-8 ] || suffix=_ACC$acc
for c in $cases; do
    case $c in
        A) run_case "A_L40_N$n$suffix" "--regular-from 5" \
            --length 40e3 --n "$n" --acc "$acc" --tmax-yr 3000 ;;
        BP2) run_case "BP2_L40_N$n$suffix" "" \
            --length 40e3 --n "$n" --acc "$acc" --tmax-yr 1200 --dc 4e-3 ;;
    esac
done
