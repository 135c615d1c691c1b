#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Runs under mpirun: the spring-slider, which has one unknown,
# started on 2 ranks must stop with one line (not one per rank) naming
# `Scene` and the rank count, exit non-zero and write nothing; on 1 rank
# under mpirun it runs (its events.csv has events). Bad input on 2 ranks
# is reported once; so is the wedge with the one-rank `Linear correction =
# direct`. The wedge on 2 ranks: killed (SIGKILL to mpirun) after a
# checkpoint and resumed on 2 ranks, its CSVs and checkpoint bitwise those
# of an uninterrupted 2-rank run; SIGINT to mpirun (which passes SIGTERM on
# to the ranks) stops it with a checkpoint and the hint "mpirun -np 2
# rsfcycle --resume", and the resumed run is again bitwise the same;
# resuming it on 1 rank is refused naming the rank count; its VTU output
# is one file per rank with a .pvtu that names them and a .pvd that names
# the .pvtu.
# Open MPI refuses to start as root (CI) without the two variables below;
# --oversubscribe allows more ranks than cores.
# Usage: mpi_ranks.sh RSFCYCLE SOURCE_DIR WORK_DIR
set -u
exe=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi=(mpirun --quiet --oversubscribe -np)
n_pass=0; n_fail=0

refused() { # name, ranks, expected words (regex), prm file
  local name=$1 ranks=$2 words=$3 prm=$4
  "${mpi[@]}" "$ranks" "$exe" "$prm" > "$name.out" 2> "$name.err"
  local status=$?
  if [ $status -ne 0 ] && [ "$(grep -c . "$name.err")" -eq 1 ] &&
     grep -q "^rsfcycle: error: " "$name.err" && grep -Eq -- "$words" "$name.err" &&
     [ ! -e "run-$name" ]; then
    n_pass=$((n_pass + 1))
  else
    n_fail=$((n_fail + 1))
    echo "FAILED $name (exit $status):"; cat "$name.err"
  fi
  echo "$name: $(cat "$name.err")"
}

printf 'include %s/prm/spring-slider.prm\nset End time = 1000\nset Output directory = run-slider\n' \
  "$src" > slider.prm
refused slider 2 "Scene = spring-slider.*one MPI rank.* 2" slider.prm

printf 'include %s/prm/spring-slider.prm\nset End time = -1\nset Output directory = run-bad\n' \
  "$src" > bad.prm
refused bad 2 "End time" bad.prm

printf 'include %s/prm/wedge-2d.prm\ninclude %s/tests/wedge-2d-pinned.prm\nset End time = 1\nset Output directory = run-wedge\n' \
  "$src" "$src" > wedge.prm
refused wedge 2 "Linear correction = direct.*one MPI rank.* 2" wedge.prm

# kill/resume on 2 ranks
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
subsection Solver
  set Linear correction = multigrid
end
subsection Output
  set Writers          = $2
  set Checkpoint steps = 20
end
PRM
}
check() { # condition (0/1), label
  if [ "$1" -eq 0 ]; then n_pass=$((n_pass + 1)); echo "$2: ok";
  else n_fail=$((n_fail + 1)); echo "FAILED $2"; fi
}
make_wedge_prm kr-a "time series, base profile, events"; make_wedge_prm kr-b "time series, base profile, events"; make_wedge_prm kr-c "time series, base profile, events"
"${mpi[@]}" 2 "$exe" kr-a.prm > kr-a.log 2>&1
check $? "2-rank wedge run"
# the VTU of 2 ranks: pieces, .pvtu naming them, .pvd naming the .pvtu
make_wedge_prm vtu "time series, base profile, events, vtu"
sed -i 's/End time = 250/End time = 20/' vtu.prm
"${mpi[@]}" 2 "$exe" vtu.prm > vtu.log 2>&1
ok=1
[ -f vtu/solution/solution-00001.0000.vtu ] && [ -f vtu/solution/solution-00001.0001.vtu ] &&
  grep -q 'Source="solution-00001.0001.vtu"' vtu/solution/solution-00001.pvtu &&
  grep -q 'file="solution/solution-00001.pvtu"' vtu/solution.pvd &&
  grep -q 'file="fault/fault-00001.pvtu"' vtu/fault.pvd &&
  [ -f vtu/fault/fault-00001.0001.vtu ] && ok=0
check $ok "VTU pieces, .pvtu and .pvd of 2 ranks"
start_and_wait() { # run folder, rows of time-series.csv to wait for
  "${mpi[@]}" 2 "$exe" "$1.prm" > "$1.log" 2>&1 &
  pid=$!
  for i in $(seq 1 1200); do
    [ -f "$1/checkpoint.bin" ] && [ -f "$1/time-series.csv" ] &&
      [ "$(wc -l < "$1/time-series.csv")" -gt "$2" ] && break
    sleep 0.05
  done
}
start_and_wait kr-b 200
kill -9 $pid; wait $pid 2>/dev/null
"${mpi[@]}" 1 "$exe" --resume kr-b > kr-b-1.log 2> kr-b-1.err
[ $? -ne 0 ] && grep -q "written on 2 MPI ranks, this run has 1: resume with mpirun -np 2" kr-b-1.err
check $? "resume of a 2-rank checkpoint on 1 rank refused"
same_as_uninterrupted() { # run folder: resume it on 2 ranks, compare with kr-a
  "${mpi[@]}" 2 "$exe" --resume $1 > $1-2.log 2>&1 || return 1
  local f ok=0
  for f in time-series.csv base-profile.csv events.csv checkpoint.bin; do
    cmp -s kr-a/$f $1/$f || { ok=1; echo "$f of $1 differs after resume on 2 ranks"; }
  done
  return $ok
}
same_as_uninterrupted kr-b
check $? "SIGKILL + resume on 2 ranks: identical to the uninterrupted run"
# (early: the whole run takes under 2 s on an idle machine, and SIGINT
# must arrive before its end)
start_and_wait kr-c 40
kill -INT $pid; wait $pid; status=$?
grep -q "Stopped by signal.*Continue with: mpirun -np 2 rsfcycle --resume" kr-c.log
check $(( status != 0 ? $? : 1 )) "SIGINT on 2 ranks: checkpoint and the resume hint (exit $status)"
same_as_uninterrupted kr-c
check $? "SIGINT + resume on 2 ranks: identical to the uninterrupted run"

sed 's/run-slider/run-one/' slider.prm > one.prm
"${mpi[@]}" 1 "$exe" one.prm > one.out 2> one.err
if [ $? -eq 0 ] && [ "$(wc -l < run-one/events.csv)" -gt 1 ]; then
  n_pass=$((n_pass + 1))
else
  n_fail=$((n_fail + 1)); echo "FAILED one rank:"; cat one.err
fi

echo "mpi ranks: $n_pass passed, $n_fail failed"
[ $n_fail -eq 0 ]
