#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# BP1-QD (prm/seas-bp1-qd.prm) to the end of its first event with both
# methods of Solver/Bulk on the same mesh, one rank each, one after the
# other: the wall time of the whole run (set-up included), the first
# event's start and its peak slip rate, from each run folder's events.csv.
# Usage, from the repository's root:
#   benchmarks/green-function/run.sh BUILD_DIR LOCAL_REFINEMENTS [volume|green|both]
# (3: 200 m cells, 4: 100 m, 5: 50 m, 6: 25 m, the .prm's.) Writes
# benchmarks/green-function/runs/<method>-<refinements>/ and one line per
# run to benchmarks/green-function/runs/first-events.txt (not tracked).
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
# die, help_if_asked
. "$root/benchmarks/common.sh"
help_if_asked "${1:-}"
[ $# -ge 2 ] || die "usage: run.sh BUILD_DIR LOCAL_REFINEMENTS [volume|green|both]"
build=$1; levels=$2; which=${3:-both}
out=$root/benchmarks/green-function/runs
mkdir -p "$out"
run() { # method, extra prm lines
  local method=$1 extra=$2 dir=$out/$1-$levels
  cat > "$out/$method-$levels.prm" <<PRM
include $root/prm/seas-bp1-qd.prm
set Output directory  = $dir
set Overwrite output  = true
set Stop after events = 1
subsection Mesh file
  set File = $root/prm/meshes/seas-bp1.msh
end
subsection Mesh
  set Local refinements = $levels
end
subsection Output
  set Write VTU = false
end
$extra
PRM
  local start=$(date +%s.%N)
  nice -n 19 "$build/rsfcycle" "$out/$method-$levels.prm" > "$out/$method-$levels.log" 2>&1
  local end=$(date +%s.%N)
  python3 - "$dir/events.csv" "$method" "$levels" "$start" "$end" <<'PY' | tee -a "$out/first-events.txt"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
e = rows[0]
wall = float(sys.argv[5]) - float(sys.argv[4])
print(f"{sys.argv[2]:6s} refinements {sys.argv[3]}: wall {wall:8.1f} s, "
      f"first event {float(e['start_s']) / 3.15576e7:.4f} yr, "
      f"peak slip rate {float(e['peak_slip_rate_m_per_s']):.4f} m/s, "
      f"nucleation {float(e['nucleation_position_m']) / 1e3:.2f} km")
PY
}
green='subsection Time stepping
  set Integrator = runge-kutta
  set Tolerance  = 1e-7
end
subsection Solver
  set Bulk = green-function
end'
if [ "$which" = green ] || [ "$which" = both ]; then run green "$green"; fi
volume='subsection Time stepping
  set Integrator = implicit
end
subsection Solver
  set Bulk = volume
end'
if [ "$which" = volume ] || [ "$which" = both ]; then run volume "$volume"; fi
