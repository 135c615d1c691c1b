#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# The Green's-function operator of prm/seas-bp5-qd.prm against Okada's (1992)
# half-space solution for a uniform strike-slip patch (README.md here).
#
# Usage:
#   OKADA_SRC=DIR benchmarks/green-function/okada/run.sh OUTDIR [REFINEMENTS...]
#
# DIR: a git clone of https://github.com/tbenthompson/okada_wrapper (for its
# copy of Okada's DC3D.f); it must be at the pinned commit below. REFINEMENTS:
# the .prm's `Mesh/Local refinements` to run (default: 1 2, i.e. 2 km and
# 1 km on the fault). Builds dc3d_points (gfortran) in OUTDIR and the target
# okada_operator_response in build/ (cmake must have configured build/), runs
# the operator on each mesh (one rank; the 1 km operator takes a few minutes)
# and compare_okada.py, which prints the tables of README.md and writes
# OUTDIR/okada-strike.png and OUTDIR/okada-depth.png.
set -euo pipefail

OKADA_COMMIT=c133989a354e317f00750ab18093b456fb69a5ff
HERE=$(cd "$(dirname "$0")" && pwd)
ROOT=$(cd "$HERE/../../.." && pwd)
PYTHON=${PYTHON:-/usr/bin/python3}
# the patch: nodes with -10 <= x <= 10 km and 4 <= depth <= 14 km slip 1 m
PATCH="-10000 10000 -14000 -4000"

# die, help_if_asked
. "$ROOT/python/rsfcycle/bench.sh"

[ $# -ge 1 ] || die "usage: OKADA_SRC=DIR run.sh OUTDIR [REFINEMENTS...]"
help_if_asked "$1"
outdir=$1
shift
refinements=${*:-1 2}
[ -n "${OKADA_SRC:-}" ] || die "set OKADA_SRC to a clone of https://github.com/tbenthompson/okada_wrapper"
[ -f "$OKADA_SRC/okada_wrapper/DC3D.f" ] || die "$OKADA_SRC has no okada_wrapper/DC3D.f"
head=$(git -C "$OKADA_SRC" rev-parse HEAD)
[ "$head" = "$OKADA_COMMIT" ] || die "$OKADA_SRC is at $head, not the pinned $OKADA_COMMIT"
[ -f "$ROOT/build/CMakeCache.txt" ] || die "configure build/ first (cmake -S . -B build)"
command -v gfortran > /dev/null || die "gfortran not found (Debian package gfortran)"

mkdir -p "$outdir"
outdir=$(cd "$outdir" && pwd)
gfortran -O2 -std=legacy -w -c "$OKADA_SRC/okada_wrapper/DC3D.f" -o "$outdir/DC3D.o"
gfortran -O2 "$HERE/dc3d_points.f90" "$outdir/DC3D.o" -o "$outdir/dc3d_points"
cmake --build "$ROOT/build" --target okada_operator_response > "$outdir/build.log"

runs=()
for r in $refinements; do
    km=$(awk -v r="$r" 'BEGIN { printf "%g", 4 / 2 ^ r }')
    echo "operator at ${km} km (Local refinements = $r)"
    /usr/bin/time -f "%e s wall, %M kB" -o "$outdir/time-${km}km.txt" \
        "$ROOT/build/okada_operator_response" "$ROOT/prm/seas-bp5-qd.prm" \
        "$r" $PATCH > "$outdir/response-${km}km.csv" 2> "$outdir/log-${km}km.txt"
    cat "$outdir/time-${km}km.txt"
    runs+=("${km} km=$outdir/response-${km}km.csv")
done
"$PYTHON" "$HERE/compare_okada.py" --dc3d "$outdir/dc3d_points" --out "$outdir" "${runs[@]}" |
    tee "$outdir/comparison.md"
