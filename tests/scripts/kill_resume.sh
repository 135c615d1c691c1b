#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Kill-and-resume test: a short coarse wedge run is killed with
# SIGKILL after it has written a checkpoint, resumed with --resume, and its
# run folder compared with that of an uninterrupted run. Expected: bitwise
# identical time-series.csv, base-profile.csv, events.csv, the SEAS files
# (wedge) and final checkpoint.bin (state vectors, counters, event detector, step controller
# with its cached candidate step): the computation is deterministic and the
# checkpoint holds everything the time loop carries. Also checks that
# SIGINT stops a run with exit code 130 and a resumable folder. The same
# for the spring-slider, which runs through the same simulator,
# with step doubling and with local extrapolation, for SEAS BP1-QD with
# Solver/Bulk = green-function (the Runge-Kutta on the fault; its VTU and
# HDF5 snapshots: the records and XDMF indices equal), and for SEAS
# BP3-QD's split fault in the volume method (its normal stress output; with
# the exact direct correction and with Direct factor reuse), and
# for Integrator = implicit-explicit (killed among its explicit steps).
# A checkpoint taken among explicit steps and resumed with a Kelvin-Voigt
# viscosity in parameters.prm (the explicit step refused) goes on with the
# implicit step and says so in its log.
# Usage: kill_resume.sh RSFCYCLE SOURCE_DIR WORK_DIR
set -u
exe=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
make_wedge_prm() {
  cat > "$1.prm" <<PRM
include $src/prm/wedge-2d.prm
include $src/tests/wedge-2d-pinned.prm
set End time = 250
set Output directory = $1
subsection Mesh
  set Global refinements = 2
  set Local refinements  = 3
end
subsection Output
  set Writers          = time series, base profile, events, seas
  set Checkpoint steps = 20
  # the SEAS files are cut and appended on resume like the CSV files
  subsection SEAS
    set Problem        = kill-resume test
    set Fault stations = 0.3
    set Slip profile   = 0.1, 0.6, 0.05
    set Slip profile interval = 5
    set Shear modulus  = 1e5
  end
end
PRM
}
# the stick-slip spring-slider with the paper's step doubling at a tight
# tolerance: long enough (about 10^5 steps) to be killed while it runs
make_slider_prm() {
  cat > "$1.prm" <<PRM
include $src/prm/spring-slider.prm
set End time = 3000
set Output directory = $1
subsection Time stepping
  set Controller = step-doubling
  set Tolerance  = 1e-9
end
subsection Output
  set Checkpoint steps = 2000
end
PRM
}
# the same with the local-extrapolation controller (the default; the wedge
# above runs with it too), whose checkpoint holds its history and a pending
# half step
make_slider_le_prm() {
  make_slider_prm "$1"
  printf 'subsection Time stepping\n  set Controller = local-extrapolation\nend\n' >> "$1.prm"
}
# SEAS BP1-QD at 200 m with Solver/Bulk = green-function through its
# first event (about 2,900 Runge-Kutta steps, each a sample, and its VTU
# snapshots of the whole body, each a static solve): the
# checkpoint holds the fault's state and ARKODE's step; the operator is
# read back from the run folder's green-operator.bin on resume and
# compressed again as an H-matrix (the same one: the product, and so every
# output, must come out bitwise the same)
make_green_prm() {
  cat > "$1.prm" <<PRM
include $src/prm/seas-bp1-qd.prm
set End time = 6.3e9
set Output directory = $1
subsection Mesh
  set Local refinements = 3
end
subsection Solver
  set Bulk = green-function
  set Green operator storage = h-matrix
end
subsection Time stepping
  set Integrator = runge-kutta
end
subsection Output
  set Checkpoint steps = 200
  set Writers = time series, base profile, events, seas, vtu, hdf5
end
PRM
}
# SEAS BP3-QD at 60 degrees on 200 m cells in the volume method, the first
# 2e8 s (about 330 steps, killed after 120): a fault between two deformable
# sides, whose SEAS files carry the normal stress
# changed by the slip (not in the checkpoint: the resumed state's is made
# from its displacement, and must come out as the run's)
make_split_prm() {
  cat > "$1.prm" <<PRM
include $src/prm/seas-bp3-qd.prm
set End time = 2e8
set Output directory = $1
subsection Mesh file
  set File = $src/prm/meshes/seas-bp3-60.msh
end
subsection Mesh
  set Global refinements = 0
  set Local refinements = 2
end
subsection Solver
  set Bulk = volume
  set Linear correction = direct
end
subsection Time stepping
  set Integrator = implicit
end
subsection Output
  set Checkpoint steps = 40
  set Writers = time series, base profile, events, seas
end
PRM
}
# the same with Solver/Direct factor reuse: the factors kept from step to
# step are not in the checkpoint, so they must not outlive a step
make_split_reuse_prm() {
  make_split_prm "$1"
  printf 'subsection Solver\n  set Direct factor reuse = true\n  set Linear correction cycles = 3\nend\n' >> "$1.prm"
}
# Integrator = implicit-explicit (tests/implicit_explicit_event.prm.in):
# its first 256 steps are explicit, so the kill after 120 rows falls among
# them, and the resumed run takes the trial of implicit steps that ends
# them; the first 200 s, before the event
make_implicit_explicit_prm() {
  sed -e "s|@SOURCE_DIR@|$src/tests|" -e "s|^set Output directory .*|set Output directory = $1|" \
    -e "s|^set End time .*|set End time = 200|" \
    "$src/tests/implicit_explicit_event.prm.in" > "$1.prm"
  printf 'subsection Output\n  set Checkpoint steps = 20\n  set Writers = time series, base profile, events\nend\n' >> "$1.prm"
}
fail() { echo "FAILED: $*"; exit 1; }
# start run $1 in the background (pid in $pid) and wait until it has
# written a checkpoint and 120 rows
start_and_wait() {
  "$exe" "$1.prm" > "$1.log" 2>&1 &
  pid=$!
  for i in $(seq 1 600); do
    [ -f "$1/checkpoint.bin" ] && [ "$(wc -l < "$1/time-series.csv")" -gt 120 ] && break
    sleep 0.05
  done
}
check_resume() { # label, prm maker
  local a=$1-a b=$1-b c=$1-c
  for r in $a $b $c; do $2 $r; done

  "$exe" $a.prm > $a.log 2>&1 || fail "uninterrupted run"
  # the SEAS files of the run, if any
  seas=$(cd $a && ls fltst_* srfst_* blkst_* *.dat 2>/dev/null)
  # the VTU records and the last snapshot, if any (compared without
  # deal.II's line with the date of writing)
  vtu="$(cd $a && ls solution.pvd fault.pvd 2>/dev/null) $(cd $a && ls solution/*.vtu 2>/dev/null | tail -1)"
  # the HDF5 snapshots' XDMF indices, if any, and the number of .h5 files
  xdmf=$(cd $a && ls solution.xdmf fault.xdmf 2>/dev/null)
  n_h5=$(ls $a/solution/*.h5 2>/dev/null | wc -l)

  start_and_wait $b
  kill -9 $pid 2>/dev/null || fail "run b ended before it could be killed"
  wait $pid 2>/dev/null
  lines_killed=$(wc -l < $b/time-series.csv)
  "$exe" --resume $b > $b-2.log 2>&1 || fail "resume after SIGKILL"
  for f in time-series.csv base-profile.csv events.csv checkpoint.bin $seas; do
    cmp -s $a/$f $b/$f || fail "$f differs after SIGKILL + resume"
  done
  for f in $vtu; do
    cmp -s <(grep -av "generated by the deal.II" $a/$f) <(grep -av "generated by the deal.II" $b/$f) ||
      fail "$f differs after SIGKILL + resume"
  done
  for f in $xdmf; do cmp -s $a/$f $b/$f || fail "$f differs after SIGKILL + resume"; done
  [ "$(ls $b/solution/*.h5 2>/dev/null | wc -l)" -eq "$n_h5" ] ||
    fail "the number of HDF5 snapshots differs after SIGKILL + resume"
  echo "$1: SIGKILL at $lines_killed rows of time-series.csv, resumed: identical"

  start_and_wait $c
  kill -INT $pid 2>/dev/null || fail "run c ended before SIGINT"
  wait $pid; status=$?
  [ $status -eq 130 ] || fail "SIGINT exit status $status, expected 130"
  grep -q "Continue with: rsfcycle --resume" $c.log || fail "no resume hint"
  "$exe" --resume $c > $c-2.log 2>&1 || fail "resume after SIGINT"
  for f in time-series.csv base-profile.csv events.csv checkpoint.bin $seas; do
    cmp -s $a/$f $c/$f || fail "$f differs after SIGINT + resume"
  done
  for f in $vtu; do
    cmp -s <(grep -av "generated by the deal.II" $a/$f) <(grep -av "generated by the deal.II" $c/$f) ||
      fail "$f differs after SIGINT + resume"
  done
  for f in $xdmf; do cmp -s $a/$f $c/$f || fail "$f differs after SIGINT + resume"; done
  echo "$1: SIGINT: exit 130, resumed: identical"
}
check_resume wedge make_wedge_prm
check_resume slider make_slider_prm
check_resume slider-local-extrapolation make_slider_le_prm
check_resume green-function make_green_prm
check_resume split-volume make_split_prm
check_resume split-volume-reuse make_split_reuse_prm
check_resume implicit-explicit make_implicit_explicit_prm

# among explicit steps, resumed with the explicit step refused
make_implicit_explicit_prm viscous
start_and_wait viscous
kill -9 $pid 2>/dev/null || fail "run viscous ended before it could be killed"
wait $pid 2>/dev/null
sed -i 's/shear viscosity 0,/shear viscosity 1e12,/' viscous/parameters.prm
grep -q "shear viscosity 1e12" viscous/parameters.prm || fail "no material to make viscous"
"$exe" --resume viscous > viscous-2.log 2>&1 || fail "resume with the explicit step refused"
grep -q "implicit steps only: the damping matrix C couples" viscous-2.log ||
  fail "the resumed log does not say that the explicit step is refused"
echo "implicit-explicit: resumed among explicit steps with the explicit step refused: implicit steps"
