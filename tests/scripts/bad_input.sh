#!/bin/bash
# Bad-input test (issue 6): each malformed parameter file must give exactly
# one line on stderr, "rsfcycle: error: ...", naming the offending entry (the
# expected word is checked), a non-zero exit status, and must not create or
# change its run folder. Covers unknown entries, misspelled subsections,
# wrong types, values out of range, inconsistent geometry, a missing file,
# an unwritable output folder and an existing run folder.
# Usage: bad_input.sh RSFCYCLE SOURCE_DIR WORK_DIR
set -u
exe=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
n_pass=0; n_fail=0

check() { # name, expected word, prm body (appended after the include)
  local name=$1 word=$2 body=$3
  printf 'include %s/prm/wedge-2d.prm\nset Output directory = run-%s\n%b\n' \
    "$src" "$name" "$body" > "$name.prm"
  "$exe" "$name.prm" > "$name.out" 2> "$name.err"
  local status=$? lines
  lines=$(wc -l < "$name.err")
  if [ $status -ne 0 ] && [ "$lines" -eq 1 ] &&
     grep -q "^rsfcycle: error: " "$name.err" &&
     grep -qi -- "$word" "$name.err" && [ ! -e "run-$name" ]; then
    n_pass=$((n_pass + 1))
  else
    n_fail=$((n_fail + 1))
    echo "FAILED $name (exit $status, $lines lines, expected '$word'):"
    cat "$name.err"
  fi
  echo "$name: $(cat "$name.err")"
}

check unknown-entry "End tim" 'set End tim = 10'
check misspelled-subsection "Wedg" 'subsection Wedg\nset Length = 1\nend'
check wrong-type "End time" 'set End time = abc'
check poisson "Poisson ratio" 'subsection Wedge\nset Poisson ratio = 0.7\nend'
check a-zero "Patch a" 'subsection Wedge\nset Patch a = 0\nend'
check L-zero "Characteristic slip distance" 'subsection Wedge\nset Characteristic slip distance = 0\nend'
check density "Density upper" 'subsection Wedge\nset Density upper = -900\nend'
check delta "Tolerance" 'subsection Time stepping\nset Tolerance = 2\nend'
check epsilon "Fixed-point tolerance" 'subsection Solver\nset Fixed-point tolerance = 0\nend'
check levels "refinements" 'subsection Mesh\nset Global refinements = 10\nset Local refinements = 10\nend'
check negative-levels "Global refinements" 'subsection Mesh\nset Global refinements = -1\nend'
check patch-beyond "Patch down-dip end" 'subsection Wedge\nset Patch down-dip end = 1.5\nend'
check patch-off-base "Patch length" 'subsection Wedge\nset Patch length = 0.5\nend'
check observation "Observation points" 'subsection Wedge\nset Observation points = 0.15, 2\nend'
check lower-region "Lower region thickness" 'subsection Wedge\nset Lower region thickness = 0.3\nend'
check dimension "Dimension" 'set Dimension = 4'
check scene "Scene" 'set Scene = cube'
check state-law "State law" 'subsection Solver\nset State law = foo\nend'
check coupling "Coupling" 'subsection Solver\nset Coupling = implicit\nend'
check correction "Linear correction" 'subsection Solver\nset Linear correction = lu\nend'
check min-step "Minimum step" 'subsection Time stepping\nset Minimum step = 1\nset Initial step = 0.1\nend'
check event-interval "Event output interval" 'subsection Output\nset Event output interval = 100\nend'
check max-iterations "Maximum fixed-point iterations" 'subsection Solver\nset Maximum fixed-point iterations = 0\nend'
check bool "Adaptive" 'subsection Time stepping\nset Adaptive = maybe\nend'

# missing parameter file
"$exe" no-such-file.prm > /dev/null 2> missing.err
if [ $? -ne 0 ] && [ "$(wc -l < missing.err)" -eq 1 ] && grep -q "no-such-file.prm" missing.err
then n_pass=$((n_pass + 1)); else n_fail=$((n_fail + 1)); echo "FAILED missing file"; fi
echo "missing-file: $(cat missing.err)"

# unwritable output folder (a path below a regular file)
touch a-file
printf 'include %s/prm/wedge-2d.prm\nset End time = 1\nset Output directory = a-file/run\n' "$src" > unwritable.prm
"$exe" unwritable.prm > /dev/null 2> unwritable.err
if [ $? -ne 0 ] && [ "$(wc -l < unwritable.err)" -eq 1 ] && grep -q "Output directory" unwritable.err
then n_pass=$((n_pass + 1)); else n_fail=$((n_fail + 1)); echo "FAILED unwritable"; cat unwritable.err; fi
echo "unwritable: $(cat unwritable.err)"

# an existing run folder is not clobbered
mkdir -p existing && echo sentinel > existing/parameters.prm
printf 'include %s/prm/wedge-2d.prm\nset End time = 1\nset Output directory = existing\n' "$src" > existing.prm
"$exe" existing.prm > /dev/null 2> existing.err
if [ $? -ne 0 ] && [ "$(wc -l < existing.err)" -eq 1 ] && grep -q -- "--force" existing.err &&
   [ "$(cat existing/parameters.prm)" = sentinel ] && [ "$(ls existing | wc -l)" -eq 1 ]
then n_pass=$((n_pass + 1)); else n_fail=$((n_fail + 1)); echo "FAILED existing"; cat existing.err; fi
echo "existing: $(cat existing.err)"

echo "bad inputs: $n_pass passed, $n_fail failed"
[ $n_fail -eq 0 ]
