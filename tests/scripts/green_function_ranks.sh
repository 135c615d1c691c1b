#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Solver/Bulk = green-function on 2 MPI ranks (each rank the rows of S of
# its contact nodes, the fault's state on every rank). SEAS BP1-QD at 200 m
# cells through its first event (about 193 years), checked:
#  - 1 and 2 ranks give the same first event: start time within 1e-6
#    relative (the ranks number the nodes differently, so the products
#    round differently), peak slip rate within 1 %, slip within 0.1 %;
#  - on 2 ranks each rank holds fewer rows than there are contact nodes
#    (the log's "rows on rank 0 of 2");
#  - the 2-rank operator file reused on 2 ranks with the H-matrix
#    (Green operator storage = h-matrix): first event within 1e-6;
#  - the 1-rank operator file refused on 2 ranks in one line naming the
#    rank counts, non-zero exit, no run folder;
#  - killed (SIGKILL) after a checkpoint and resumed on 2 ranks: every
#    output file and checkpoint.bin bitwise those of the uninterrupted run;
#  - the implicit step on the fault (Integrator = implicit, tolerances
#    1e-4): the same first event on 1 and 2 ranks (start within 1e-5: the
#    fault solver stops at its tolerance, which the rounding moves), and
#    killed and resumed on 2 ranks bitwise (the step-size control's memory
#    in the checkpoint);
#  - 3D (tests/meshes/box-fault-3d.prm: two slip components per node, the
#    state per node): the same first event on 1 and 2 ranks (1e-6).
#  - a fault between two deformable sides (tests/meshes/split-fault-2d.msh,
#    plane strain, the sides tied across the ranks' parts of the mesh,
#    physics/split_fault.h): the same first event on 1 and 2 ranks (1e-6,
#    at the Runge-Kutta tolerance 1e-9: at the shipped 1e-5 the rounding
#    that differs between the ranks' sums moves this plane-strain event by
#    2e-5 through the adaptive steps).
#  - the same on a fault dipping 60 degrees whose two sides are meshed
#    apart with unstructured cells (tests/meshes/dipping-split-2d.msh,
#    thrust, refined twice toward the fault: the refinement matched on both
#    sides, physics::refine_fault_sides_alike): runs on 1 and 2 ranks (the
#    ranks' parts of the fault differ), the same number of contact nodes,
#    the same first event (1e-6).
# Usage: green_function_ranks.sh RSFCYCLE SOURCE_DIR WORK_DIR
set -u
exe=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi=(mpirun --quiet --oversubscribe -np)
n_pass=0; n_fail=0
check() { # condition (0/1), label
  if [ "$1" -eq 0 ]; then n_pass=$((n_pass + 1)); echo "$2: ok";
  else n_fail=$((n_fail + 1)); echo "FAILED $2"; fi
}
make_prm() { # name, extra lines
  local name=$1; shift
  cat > "$name.prm" <<PRM
include $src/prm/seas-bp1-qd.prm
set End time = 6.3e9
set Output directory = $name
subsection Mesh
  set Local refinements = 3
end
subsection Solver
  set Bulk = green-function
end
subsection Time stepping
  set Integrator = runge-kutta
end
subsection Output
  set Checkpoint steps = 200
end
PRM
  printf '%s\n' "$@" >> "$name.prm"
}
# first event of two events.csv: start, peak, slip within the bounds
same_event() { # a, b, relative bound on the start
  python3 - "$1/events.csv" "$2/events.csv" "$3" <<'PY'
import csv, sys
a, b = (next(csv.DictReader(open(f))) for f in sys.argv[1:3])
bound = float(sys.argv[3])
rel = lambda k: abs(float(a[k]) - float(b[k])) / abs(float(b[k]))
print("start %.2e, peak %.2e, slip %.2e relative" %
      (rel("start_s"), rel("peak_slip_rate_m_per_s"), rel("slip_um")))
sys.exit(0 if rel("start_s") < bound and rel("peak_slip_rate_m_per_s") < 1e-2
         and rel("slip_um") < 1e-3 else 1)
PY
}

make_prm one; make_prm two
"${mpi[@]}" 1 "$exe" one.prm > one.log 2>&1
check $? "1-rank run"
"${mpi[@]}" 2 "$exe" two.prm > two.log 2>&1
check $? "2-rank run"
same_event two one 1e-6
check $? "first event on 2 ranks as on 1"
rows=$(sed -n 's/.*(\([0-9]*\) rows on rank 0 of 2[);].*/\1/p' two.log)
nodes=$(sed -n 's/.*operator \([0-9]*\) x .*/\1/p' two.log)
[ -n "$rows" ] && [ "$rows" -lt "$nodes" ]
check $? "rank 0 holds $rows of $nodes rows"

make_prm reuse "subsection Solver" "  set Green operator storage = h-matrix" \
  "  set Green operator file = two/green-operator.bin" "end"
"${mpi[@]}" 2 "$exe" reuse.prm > reuse.log 2>&1 &&
  grep -q "as an H-matrix" reuse.log && grep -q "read from .*two/green-operator.bin" reuse.log
check $? "2-rank operator file reused on 2 ranks, compressed"
same_event reuse two 1e-6
check $? "first event with the H-matrix as with the dense rows"

make_prm foreign "subsection Solver" \
  "  set Green operator file = one/green-operator.bin" "end"
"${mpi[@]}" 2 "$exe" foreign.prm > foreign.out 2> foreign.err
status=$?
[ $status -ne 0 ] && [ "$(grep -c . foreign.err)" -eq 1 ] &&
  grep -q "written on 1 MPI rank(s), this run has 2" foreign.err && [ ! -e foreign ]
check $? "1-rank operator file refused on 2 ranks (exit $status): $(cat foreign.err)"

make_prm killed
"${mpi[@]}" 2 "$exe" killed.prm > killed.log 2>&1 &
pid=$!
for i in $(seq 1 1200); do
  [ -f killed/checkpoint.bin ] && [ -f killed/time-series.csv ] &&
    [ "$(wc -l < killed/time-series.csv)" -gt 1500 ] && break
  sleep 0.05
done
kill -9 $pid; wait $pid 2>/dev/null
! grep -q "^Summary" killed.log
check $? "killed before its end"
"${mpi[@]}" 2 "$exe" --resume killed > killed-2.log 2>&1
ok=$?
for f in time-series.csv events.csv base-profile.csv checkpoint.bin $(cd two && ls fltst_* devol.dat); do
  cmp -s two/$f killed/$f || { ok=1; echo "$f differs after the resume"; }
done
check $ok "SIGKILL + resume on 2 ranks: identical to the uninterrupted run"

implicit=("subsection Time stepping" "  set Integrator = implicit"
  "  set Tolerance = 1e-4" "end" "subsection Solver"
  "  set Fixed-point tolerance = 1e-4" "end")
make_prm implicit-one "${implicit[@]}"; make_prm implicit-two "${implicit[@]}"
make_prm implicit-killed "${implicit[@]}"
"${mpi[@]}" 1 "$exe" implicit-one.prm > implicit-one.log 2>&1 &&
  "${mpi[@]}" 2 "$exe" implicit-two.prm > implicit-two.log 2>&1 &&
  grep -q "the implicit step on the fault" implicit-two.log
check $? "implicit step on 1 and 2 ranks"
same_event implicit-two implicit-one 1e-5
check $? "implicit step: first event on 2 ranks as on 1"
"${mpi[@]}" 2 "$exe" implicit-killed.prm > implicit-killed.log 2>&1 &
pid=$!
for i in $(seq 1 1200); do
  [ -f implicit-killed/checkpoint.bin ] && [ -f implicit-killed/time-series.csv ] &&
    [ "$(wc -l < implicit-killed/time-series.csv)" -gt 1500 ] && break
  sleep 0.05
done
kill -9 $pid; wait $pid 2>/dev/null
! grep -q "^Summary" implicit-killed.log
check $? "implicit step killed before its end"
"${mpi[@]}" 2 "$exe" --resume implicit-killed > implicit-killed-2.log 2>&1
ok=$?
for f in time-series.csv events.csv base-profile.csv checkpoint.bin $(cd implicit-two && ls fltst_* devol.dat); do
  cmp -s implicit-two/$f implicit-killed/$f || { ok=1; echo "$f differs after the resume"; }
done
check $ok "implicit step: SIGKILL + resume on 2 ranks identical to the uninterrupted run"

for n in 1 2; do
  cat > box-$n.prm <<PRM
include $src/tests/meshes/box-fault-3d.prm
set Output directory = box-$n
subsection Solver
  set Bulk = green-function
end
subsection Time stepping
  set Integrator = runge-kutta
  set Tolerance = 1e-7
  set Initial step = 1e5
  set Maximum step = 3.15576e7
end
PRM
  "${mpi[@]}" $n "$exe" box-$n.prm > box-$n.log 2>&1
  check $? "3D run on $n rank(s)"
done
same_event box-2 box-1 1e-6
check $? "3D: first event on 2 ranks as on 1"

material="density 2670, bulk modulus 53.39686e9, Poisson ratio 0.25, shear viscosity 0, bulk viscosity 0"
split=("set Displacement = vector" "subsection Mesh file"
  "  set File = $src/tests/meshes/split-fault-2d.msh"
  "  set Boundary roles = 1: contact, 2: creep, 3: free, 4: free, 5: load, 11: fault-opposite, 12: fault-opposite, 13: free, 14: free, 15: load-opposite"
  "  set Materials = 10: $material; 20: $material" "  set Gravity = 0, 0"
  "  set Load velocity = 0, 5e-10"
  "  set Observation points = fn+02: 2e3, 0; fn-02: -2e3, 0" "end"
  "subsection Output" "  set Writers = time series, base profile, events"
  "  subsection SEAS" "    set Benchmark = none" "  end" "end"
  "subsection Time stepping" "  set Tolerance = 1e-9" "end")
# NAME-1 and NAME-2 from the prm lines, run on 1 and 2 ranks: the same
# first event
on_1_and_2_ranks() { # name, label, prm lines
  local name=$1 label=$2
  shift 2
  make_prm "$name-1" "$@"; make_prm "$name-2" "$@"
  "${mpi[@]}" 1 "$exe" "$name-1.prm" > "$name-1.log" 2>&1
  check $? "$label on 1 rank"
  "${mpi[@]}" 2 "$exe" "$name-2.prm" > "$name-2.log" 2>&1
  check $? "$label on 2 ranks"
  same_event "$name-2" "$name-1" 1e-6
  check $? "$label: first event on 2 ranks as on 1"
}
on_1_and_2_ranks split "split fault" "${split[@]}"

a="if(-y / 0.8660254 < 15e3, 0.01, if(-y / 0.8660254 < 18e3, 0.01 + 0.015 * (-y / 0.8660254 - 15e3) / 3e3, 0.025))"
dipping=("set Displacement = vector" "set Stop after events = 1"
  "set End time = 1.5e10" "subsection Mesh file"
  "  set File = $src/tests/meshes/dipping-split-2d.msh"
  "  set Boundary roles = 1: contact, 2: creep, 3: free, 4: free, 5: load, 11: fault-opposite, 12: fault-opposite, 15: load-opposite"
  "  set Materials = 10: $material; 20: $material" "  set Gravity = 0, 0"
  "  set Load velocity = -2.5e-10, 4.330127e-10" "  set Refine where = 1"
  "  set Observation points = fn+08: 8e3, 0; fn-08: -8e3, 0"
  "  subsection Friction" "    set a = $a" "    set b - a = 0.015 - ($a)"
  "    set Initial state = 8e-3 / 1e-6 * exp((($a) * ln(2e-6 / 1e-9 * sinh(50e6 * 0.025 * asinh(1e-9 / 2e-6 * exp((0.6 + 0.015 * ln(1e-6 / 1e-9)) / 0.025)) / (($a) * 50e6))) - 0.6) / 0.015)"
  "  end" "end" "subsection Mesh" "  set Local refinements = 2" "end"
  "subsection Output" "  set Writers = time series, base profile, events"
  "  subsection SEAS" "    set Benchmark = none" "  end" "end"
  "subsection Time stepping" "  set Tolerance = 1e-9" "end")
on_1_and_2_ranks dipping "dipping split fault, unstructured sides" \
  "${dipping[@]}"
nodes1=$(sed -n 's/.* \([0-9]*\) contact nodes.*/\1/p' dipping-1.log)
nodes2=$(sed -n 's/.* \([0-9]*\) contact nodes.*/\1/p' dipping-2.log)
[ -n "$nodes1" ] && [ "$nodes1" = "$nodes2" ]
check $? "dipping split fault: $nodes1 and $nodes2 contact nodes on 1 and 2 ranks"

echo "green-function on ranks: $n_pass passed, $n_fail failed"
[ $n_fail -eq 0 ]
