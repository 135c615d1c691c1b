#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# What a new user meets first (doc/running.md): (1) `rsfcycle --version`
# prints "rsfcycle X.Y.Z, commit C, deal.II A.B.C, Release|Debug", and
# --help names the mesh-file scene and every shipped .prm; (2) a parameter
# file that includes a file naming its mesh relative to that file's own
# folder runs from another working directory, its run folder's
# parameters.prm records the absolute path (so --resume works from a third
# folder), and log.txt and parameters.prm start with the --version line;
# (3) a mesh path found neither beside the parameter file nor in the
# working directory stops the run with status 1 and one line naming the
# entry and both paths tried, writing nothing; (4) a run stopped by SIGINT
# exits with 130 and its timer table shows the time spent stepping (at
# least the second it was left to step), not 0 s.
# Usage: paths_and_version.sh RSFCYCLE SOURCE_DIR WORK_DIR
set -u
exe=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work/project/meshes" "$work/elsewhere"
cd "$work/elsewhere" || exit 1
fail() { echo "FAILED: $*"; exit 1; }

# (1) the version line
version=$("$exe" --version) || fail "--version exits with $?"
echo "$version" | grep -Eq '^rsfcycle [0-9]+\.[0-9]+\.[0-9]+, commit [^,]+, deal\.II [0-9]+\.[0-9]+\.[0-9]+, (Release|Debug)$' ||
  fail "--version printed '$version'"
echo "--version: pattern ok"
help=$("$exe" --help) || fail "--help exits with $?"
for name in mesh-file $(cd "$src/prm" && ls *.prm); do
  echo "$help" | grep -q -- "$name" || fail "--help does not name $name"
done
echo "--help: names the mesh-file scene and every file of prm/"

# (2) the coarse mesh-file wedge with its mesh in the parameter file's
# project folder, run from another folder
# The mesh is named in an included file, relative to that file's folder.
cp "$src/tests/meshes/wedge-simplex-2d.msh" "$work/project/meshes/"
mkdir -p "$work/project/common"
cat > "$work/project/common/mesh.prm" <<PRM
subsection Mesh file
  set File      = ../meshes/wedge-simplex-2d.msh
  set Materials = 10: density 900, bulk modulus 5e4, Poisson ratio 0.3, shear viscosity 1e3, bulk viscosity 1e3
end
PRM
cat > "$work/project/short.prm" <<PRM
include $src/prm/wedge-2d-mesh.prm
include $src/tests/wedge-2d-pinned.prm
include common/mesh.prm
set End time         = 20
set Output directory = run
subsection Mesh
  set Global refinements = 2
  set Local refinements  = 2
end
subsection Output
  set Writers = time series, base profile, events
end
PRM
"$exe" ../project/short.prm > short.log 2>&1 || { cat short.log; fail "run from another folder exits with $?"; }
grep -q "set File *= $work/project/meshes/wedge-simplex-2d.msh " run/parameters.prm ||
  fail "parameters.prm does not record the absolute mesh path"
[ "$(head -1 run/log.txt)" = "$version" ] || fail "log.txt does not start with the version line"
[ "$(head -1 run/parameters.prm)" = "# $version" ] ||
  fail "parameters.prm does not start with the version line"
echo "run from another folder: ok, absolute path and version recorded"

# ... and --resume of that folder from a third folder reads the recorded path
mkdir -p "$work/third" && cd "$work/third" || exit 1
cp -r "$work/elsewhere/run" resumed
sed -i 's/^set End time *=.*/set End time = 25/' resumed/parameters.prm
"$exe" --resume resumed > resume.log 2>&1 || fail "resume from another folder: $(tail -1 resume.log)"
grep -q "^Resumed from the checkpoint at t = 20 s" resume.log || fail "resume: not resumed at t = 20 s"
echo "resume from another folder: the recorded mesh path is found, run continued"
cd "$work/elsewhere" || exit 1

# (3) a mesh path that resolves nowhere
sed 's|include common/mesh.prm|subsection Mesh file\n  set File = meshes/missing.msh\nend|; s|= run$|= run-missing|' \
  "$work/project/short.prm" > "$work/project/missing.prm"
"$exe" ../project/missing.prm > missing.log 2>&1
status=$?
[ $status -eq 1 ] || fail "missing mesh: exit status $status, expected 1"
[ "$(wc -l < missing.log)" -eq 1 ] || fail "missing mesh: not one line: $(cat missing.log)"
grep -q "Mesh file/File = meshes/missing.msh" missing.log || fail "the entry is not named: $(cat missing.log)"
grep -q "$work/project/meshes/missing.msh" missing.log || fail "the .prm's folder is not named"
grep -q "$work/elsewhere/meshes/missing.msh" missing.log || fail "the working directory is not named"
[ -e run-missing ] && fail "missing mesh: the run folder was written"
echo "missing mesh: one line, both paths named, nothing written"

# (4) SIGINT after the run has stepped for a while: a true timer table
sed 's/^set End time .*/set End time = 100000/; s|= run$|= run-sigint|' \
  "$work/project/short.prm" > "$work/project/sigint.prm"
"$exe" ../project/sigint.prm > sigint.log 2>&1 &
pid=$!
for i in $(seq 1 600); do
  grep -q '^\*\*\* Step' sigint.log && break
  sleep 0.05
done
sleep 2
kill -INT $pid
wait $pid
status=$?
[ $status -eq 130 ] || fail "SIGINT: exit status $status, expected 130"
grep -q "Stopped by signal 2" sigint.log || fail "SIGINT: no stop message"
stepping=$(awk -F'|' '$2 ~ /^ *Time stepping *$/ {gsub(/[ s]/, "", $4); print $4}' sigint.log)
[ -n "$stepping" ] || fail "SIGINT: no Time stepping row in the timer table"
awk -v t="$stepping" 'BEGIN {exit !(t >= 1.0)}' ||
  fail "SIGINT: Time stepping shows $stepping s after at least 2 s of stepping"
echo "SIGINT: exit 130, the timer table shows the stepping time (>= 1 s)"
echo "all checks passed"
