#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Before and after a restructuring: the same runs with two binaries, timed
# in turn by farm-bench (A B A B ..., the ratio taken pair by pair), and
# their outputs compared bitwise.
#   (a) the stick-slip spring-slider, prm/spring-slider.prm (500 s, implicit
#       step, ARKODE-free), 5 pairs;
#   (b) the 2D wedge, prm/wedge-2d.prm on 1 rank at 2 global + 4 local
#       refinements over 0 - 560 s (the ramp, the interseismic loading and
#       the first events), 3 pairs.
# Each binary reads the parameter files of its own commit (OLD_COMMIT's
# from git, the working tree's for the new one), since entries moved.
# Usage: bash benchmarks/time-stepping/before_after.sh OLD_BINARY OLD_COMMIT NEW_BINARY WORK
# WORK (or the environment's BEFORE_AFTER_WORK): a scratch folder, emptied
# first. farm-bench must be on the PATH.
set -euo pipefail
src=$(cd "$(dirname "$0")/../.." && pwd)
# die, help_if_asked
. "$src/benchmarks/common.sh"
help_if_asked "${1:-}"
[ $# -ge 3 ] || die "usage: before_after.sh OLD_BINARY OLD_COMMIT NEW_BINARY WORK"
old=$1; old_commit=$2; new=$3; work=${4:-${BEFORE_AFTER_WORK:-}}
[ -n "$work" ] || die "give a scratch folder: the fourth argument WORK or BEFORE_AFTER_WORK=DIR"
rm -rf "$work"; mkdir -p "$work/old" "$work/new"
git -C "$src" show "$old_commit:prm/spring-slider.prm" > "$work/old/spring-slider.prm"
git -C "$src" show "$old_commit:prm/wedge-2d.prm" > "$work/old/wedge-2d.prm"
cp "$src/prm/spring-slider.prm" "$src/prm/wedge-2d.prm" "$work/new/"
for side in old new; do
  cat > "$work/$side/wedge.prm" <<PRM
include $work/$side/wedge-2d.prm
set End time = 560
set Output directory = $work/$side/wedge-run
subsection Mesh
  set Global refinements = 2
  set Local refinements  = 4
end
subsection Output
  set Write VTU = false
end
PRM
  cat > "$work/$side/slider.prm" <<PRM
include $work/$side/spring-slider.prm
set Output directory = $work/$side/slider-run
PRM
done
cd "$work"
echo "== (a) spring-slider, A = new ($new), B = old ($old)"
farm-bench -n 5 --timeout 600 --vs "$old --force old/slider.prm" -- "$new" --force new/slider.prm
echo "== (b) 2D wedge 0 - 560 s, 1 rank, A = new, B = old"
farm-bench -n 3 --warmup 0 --timeout 3000 --vs "$old --force old/wedge.prm" -- "$new" --force new/wedge.prm
echo "== outputs"
for f in slider-run/time-series.csv slider-run/events.csv wedge-run/time-series.csv \
         wedge-run/events.csv wedge-run/base-profile.csv; do
  if cmp -s "old/$f" "new/$f"; then echo "$f: identical"; else echo "$f: DIFFERS"; fi
done
grep -h "^Summary" old/wedge-run/log.txt new/wedge-run/log.txt
