#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# The Green's-function operator file (Solver/Bulk = green-function): every
# run writes green-operator.bin to its run folder; `Solver/Green operator
# file` reuses it in a new run (a relative path beside the .prm), which
# must then give bitwise the same results as the run that computed it;
# a damaged, truncated or foreign file (another mesh, another material)
# is refused in one line naming the entry, with a non-zero exit and no
# run folder; a resume whose folder holds a damaged operator is refused
# with the folder unchanged; the entry without green-function is refused.
# SEAS BP1-QD at 200 m cells over 30 years (no event).
# Usage: green_operator_file.sh RSFCYCLE SOURCE_DIR WORK_DIR
set -u
exe=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work/prm"; cd "$work" || exit 1
fail() { echo "FAILED: $*"; exit 1; }
# make_prm NAME [extra lines]: the run NAME into $work/NAME
make_prm() {
  local name=$1; shift
  cat > "prm/$name.prm" <<PRM
include $src/prm/seas-bp1-qd.prm
set End time = 1e9
set Output directory = $work/$name
subsection Mesh
  set Local refinements = 3
end
subsection Solver
  set Bulk = green-function
end
subsection Time stepping
  set Integrator = runge-kutta
end
PRM
  printf '%s\n' "$@" >> "prm/$name.prm"
}
# refused NAME PATTERN: the run NAME fails in one line matching PATTERN
# and leaves no run folder
refused() {
  "$exe" "prm/$1.prm" > "$1.out" 2> "$1.err" && fail "$1: the run was not refused"
  [ "$(wc -l < "$1.err")" -eq 1 ] || fail "$1: the refusal is not one line: $(cat "$1.err")"
  grep -q -- "$2" "$1.err" || fail "$1: the refusal does not say '$2': $(cat "$1.err")"
  [ -e "$1" ] && fail "$1: a run folder was written"
  echo "$1 refused: $(cat "$1.err")"
}

make_prm a
"$exe" prm/a.prm > a.out 2>&1 || fail "run a"
[ -s a/green-operator.bin ] || fail "run a wrote no green-operator.bin"
grep -q "block solves" a/log.txt || fail "run a did not compute the operator"

# reuse, the path relative to the .prm's folder
make_prm b "subsection Solver" "  set Green operator file = ../a/green-operator.bin" "end"
"$exe" prm/b.prm > b.out 2>&1 || fail "run b"
grep -q "read from $work/a/green-operator.bin" b/log.txt || fail "run b did not read a's operator"
for f in green-operator.bin time-series.csv events.csv base-profile.csv devol.dat fltst_dp075; do
  cmp -s a/$f b/$f || fail "$f differs between the computed and the read operator"
done
echo "b: read a's operator, results bitwise identical"

# damaged (one byte of the payload), truncated
cp a/green-operator.bin damaged.bin
printf '\x55' | dd of=damaged.bin bs=1 seek=5000 conv=notrunc status=none
make_prm c "subsection Solver" "  set Green operator file = $work/damaged.bin" "end"
refused c "Solver/Green operator file: .*damaged"
head -c 100000 a/green-operator.bin > truncated.bin
make_prm d "subsection Solver" "  set Green operator file = $work/truncated.bin" "end"
refused d "truncated"
# another mesh, another material (the same sizes)
make_prm e "subsection Mesh" "  set Local refinements = 2" "end" \
  "subsection Solver" "  set Green operator file = $work/a/green-operator.bin" "end"
refused e "written for .* unknowns"
make_prm f "subsection Mesh file" \
  "  set Materials = 10: density 1335, bulk modulus 30e9, Poisson ratio 0.25, shear viscosity 0, bulk viscosity 0" \
  "end" "subsection Solver" "  set Green operator file = $work/a/green-operator.bin" "end"
refused f "another stiffness"
# the entry without the method
make_prm g "subsection Solver" "  set Bulk = volume" \
  "  set Green operator file = $work/a/green-operator.bin" "end" \
  "subsection Time stepping" "  set Integrator = implicit" "end"
refused g "needs Solver/Bulk = green-function"

# a resume whose operator is damaged: refused, the folder unchanged
cp -r a h
cp damaged.bin h/green-operator.bin
before=$(cd h && ls -l --time-style=+%s.%N && md5sum *)
"$exe" --resume h > h.out 2> h.err && fail "resume with a damaged operator was not refused"
grep -q -- "--resume: .*damaged" h.err || fail "resume refusal: $(cat h.err)"
[ "$(cd h && ls -l --time-style=+%s.%N && md5sum *)" = "$before" ] || fail "the refused resume changed the folder"
echo "h: resume with a damaged operator refused: $(cat h.err)"
echo "PASSED"
