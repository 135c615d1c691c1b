#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# Bad-input test: each malformed parameter file must give exactly
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

check_file() { # name, expected word: run NAME.prm and check the refusal
  local name=$1 word=$2
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

check() { # name, expected word, prm body (appended after the include)
  local name=$1 word=$2 body=$3
  printf 'include %s/prm/wedge-2d.prm\nset Output directory = run-%s\n%b\n' \
    "$src" "$name" "$body" > "$name.prm"
  check_file "$name" "$word"
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
check seas-modulus "Shear modulus" 'subsection Output\nsubsection SEAS\nset Problem = BP1\nend\nend'
check seas-profile "Slip profile" 'subsection Output\nsubsection SEAS\nset Problem = BP1\nset Shear modulus = 1e10\nset Slip profile = 0, 1, 0\nend\nend'
check seas-stations "Fault stations" 'subsection Output\nsubsection SEAS\nset Problem = BP1\nset Shear modulus = 1e10\nset Fault stations = 0.1, 0.3\nend\nend'
check bool "Adaptive" 'subsection Time stepping\nset Adaptive = maybe\nend'
check theta "Theta" 'subsection Solver\nset Theta = 0.4\nend'
check dynamics "Dynamics" 'subsection Solver\nset Dynamics = quasi\nend'
check antiplane-wedge "Displacement = antiplane" 'set Displacement = antiplane'

# Scene = mesh-file: tags, cells, the contact's plane, the
# vectors and the function-valued friction; the meshes are in tests/meshes.
check_mesh() { # name, expected word, mesh (in tests/meshes), prm body
  local name=$1 word=$2 mesh=$3 body=$4
  printf 'include %s/prm/wedge-2d-mesh.prm\nset Output directory = run-%s\nsubsection Mesh file\nset File = %s/tests/meshes/%s\n%b\nend\n' \
    "$src" "$name" "$src" "$mesh" "$body" > "$name.prm"
  check_file "$name" "$word"
}
simplex=wedge-simplex-2d.msh
one_material='set Materials = 10: density 900, bulk modulus 5e4, Poisson ratio 0.3, shear viscosity 1e3, bulk viscosity 1e3'
check_mesh mesh-missing "File = " no-such.msh "$one_material"
check_mesh mesh-triangles "quadrilaterals" triangles-2d.msh "$one_material"
check_mesh mesh-tag-without-role "boundary tag 3 has no role" $simplex "$one_material\nset Boundary roles = 1: contact, 2: load"
check_mesh mesh-role-without-tag "tag 7 (free) is not a boundary tag" $simplex "$one_material\nset Boundary roles = 1: contact, 2: load, 3: free, 7: free"
check_mesh mesh-no-contact "no tag has the role contact" $simplex "$one_material\nset Boundary roles = 1: free, 2: load, 3: free"
check_mesh mesh-two-roles "tag 3 has two roles" $simplex "$one_material\nset Boundary roles = 1: contact, 2: load, 3: free, 3: load"
check_mesh free-normal-without-stress "Contact normal = free: needs Friction/Normal stress" $simplex "$one_material\nset Contact normal = free"
check_mesh mesh-unknown-role "Boundary roles" $simplex "$one_material\nset Boundary roles = 1: contact, 2: push, 3: free"
check_mesh mesh-volume-without-material "volume tag 10 has no material" $simplex 'set Materials = 11: density 900, bulk modulus 5e4, Poisson ratio 0.3, shear viscosity 1e3, bulk viscosity 1e3'
check_mesh mesh-material-property "Poisson ratio" $simplex 'set Materials = 10: density 900, bulk modulus 5e4, Poisson ratio 0.6, shear viscosity 1e3, bulk viscosity 1e3'
check_mesh mesh-curved-contact "not planar" bent-2d.msh "$one_material"
check_mesh mesh-free-slip "free-slip" $simplex "$one_material\nset Boundary roles = 1: contact, 2: load, 3: free-slip"
check_mesh mesh-load-normal "Load velocity" $simplex "$one_material\nset Load velocity = 0, -50e-6"
check_mesh mesh-gravity-components "Gravity" $simplex "$one_material\nset Gravity = 0, 0, -9.81"
check_mesh mesh-observation "Observation points" $simplex "$one_material\nset Observation points = far: 5, 0"
check_mesh mesh-expression "Friction/a" $simplex "$one_material\nsubsection Friction\nset a = if(x >\nend"
check_mesh mesh-negative-a "Friction/a" $simplex "$one_material\nsubsection Friction\nset a = 0.01 - x\nend"
check_mesh mesh-initial-state "Friction/Initial state" $simplex "$one_material\nsubsection Friction\nset Initial state = -1\nend"
check_mesh mesh-normal-stress "Friction/Normal stress" $simplex "$one_material\nsubsection Friction\nset Normal stress = 1e6 * (x - 0.5)\nend"
check_mesh mesh-antiplane-normal-stress "Normal stress" $simplex "$one_material\nset Load velocity = 50e-6\nend\nset Displacement = antiplane\nsubsection Mesh file"
check_mesh mesh-antiplane-load "Load velocity" $simplex "$one_material\nend\nset Displacement = antiplane\nsubsection Mesh file"
check_mesh mesh-seas-station "Output/SEAS/Fault stations: 100 m lies outside the contact" $simplex "$one_material\nend\nsubsection Output\nsubsection SEAS\nset Problem = BP1\nset Shear modulus = 1e10\nset Fault stations = 0, 100\nset Slip profile = 0, 0.1, 0.05\nend\nend\nsubsection Mesh file"
check_mesh mesh-radiation-damping "Friction/Radiation damping" $simplex "$one_material\nsubsection Friction\nset Radiation damping = -1\nend"

# Solver/Bulk = green-function: what the fault's Green's functions cannot
# represent (inertia, no radiation damping, gravity's normal stress that
# changes with slip, Kelvin-Voigt viscosity, a load ramp), the integrator it
# needs, and runge-kutta without it. On SEAS BP1-QD (mesh-file, antiplane)
# and the wedge (normal stress from gravity).
check_bp1() { # name, expected word, prm body (appended after the include)
  local name=$1 word=$2 body=$3
  printf 'include %s/prm/seas-bp1-qd.prm\nset Output directory = run-%s\nsubsection Mesh file\nset File = %s/prm/meshes/seas-bp1.msh\nend\nsubsection Time stepping\nset Integrator = runge-kutta\nend\nsubsection Solver\nset Bulk = green-function\nend\n%b\n' \
    "$src" "$name" "$src" "$body" > "$name.prm"
  check_file "$name" "$word"
}
check_bp1 green-inertia "Dynamics = quasi-dynamic" 'subsection Solver\nset Dynamics = dynamic\nend'
check_bp1 green-quasi-static "Dynamics = quasi-dynamic" 'subsection Solver\nset Dynamics = quasi-static\nend'
check_bp1 free-normal-antiplane "Contact normal = free: not with Displacement = antiplane" 'subsection Mesh file\nset Contact normal = free\nend'
check_bp1 green-integrator "Integrator = runge-kutta or implicit" 'subsection Time stepping\nset Integrator = arkode\nend'
check_bp1 green-viscosity "shear viscosity" 'subsection Mesh file\nset Materials = 10: density 1335, bulk modulus 26.69843e9, Poisson ratio 0.25, shear viscosity 1e12, bulk viscosity 0\nend'
check_bp1 green-ramp "Ramp time" 'subsection Mesh file\nset Ramp time = 3e7\nend'
check_bp1 sponge-quasi-dynamic "Sponge damping: needs Solver/Dynamics = dynamic" 'subsection Mesh file\nset Sponge damping = 1\nend'
check_bp1 sponge-negative "Sponge damping = -1 at" 'subsection Solver\nset Dynamics = dynamic\nend\nsubsection Mesh file\nset Sponge damping = -1\nend'
# (these two need the assembled matrices: refused after the set-up, still
# before the run folder is touched)
check_bp1 green-cohesion "Cohesion = 0" 'subsection Mesh file\nsubsection Friction\nset Cohesion = 1e5\nend\nend'
check_bp1 green-dashpots "dashpots" 'subsection Mesh file\nset Boundary roles = 1: contact, 2: load, 3: free, 4: absorbing, 5: load\nend'
check green-gravity "Normal stress" 'subsection Solver\nset Dynamics = quasi-dynamic\nset Bulk = green-function\nend\nsubsection Time stepping\nset Integrator = runge-kutta\nend'
check runge-kutta-volume "Bulk = green-function" 'subsection Time stepping\nset Integrator = runge-kutta\nend'
check explicit-quasi-static "Integrator = explicit: needs Solver/Dynamics = dynamic" 'subsection Solver\nset Dynamics = quasi-static\nend\nsubsection Time stepping\nset Integrator = explicit\nend'
check explicit-consistent-mass "Integrator = implicit-explicit: needs Solver/Mass matrix = lumped" 'subsection Time stepping\nset Integrator = implicit-explicit\nend'
check explicit-viscous "Integrator = explicit: needs inviscid" 'subsection Solver\nset Dynamics = dynamic\nset Mass matrix = lumped\nend\nsubsection Time stepping\nset Integrator = explicit\nend'
# A fault between two deformable sides (tests/meshes/split-fault-2d.msh):
# the volume method with multigrid (only the direct correction ties the two
# sides so far), gravity, a free
# contact normal, and an other side whose nodes do not all pair (tag 12
# given the role free: the creeping fault's nodes have no partner; refused
# after the set-up, before the run folder).
split="subsection Mesh file\nset File = $src/tests/meshes/split-fault-2d.msh\nset Materials = 10: density 2670, bulk modulus 53.39686e9, Poisson ratio 0.25, shear viscosity 0, bulk viscosity 0; 20: density 2670, bulk modulus 53.39686e9, Poisson ratio 0.25, shear viscosity 0, bulk viscosity 0\nset Gravity = 0, 0\nset Observation points =\nset Boundary roles = %ROLES%\nend\nsubsection Output\nset Writers = time series, base profile, events\nsubsection SEAS\nset Benchmark = none\nend\nend"
check_split() { # name, expected word, roles, prm body
  check_bp1 "$1" "$2" "${split//%ROLES%/$3}\n$4"
}
check_split split-volume "Linear correction: a fault-opposite side" "1: contact, 2: creep, 3: free, 4: free, 5: load, 11: fault-opposite, 12: fault-opposite, 13: free, 14: free, 15: load-opposite" 'subsection Solver\nset Bulk = volume\nend\nsubsection Time stepping\nset Integrator = implicit\nend'
check_split split-gravity "Gravity = 0" "1: contact, 2: creep, 3: free, 4: free, 5: load, 11: fault-opposite, 12: fault-opposite, 13: free, 14: free, 15: load-opposite" 'subsection Mesh file\nset Gravity = 0, -9.81\nend'
check_split split-unpaired "has no node of a fault-opposite face" "1: contact, 2: creep, 3: free, 4: free, 5: load, 11: fault-opposite, 12: free, 13: free, 14: free, 15: load-opposite" ''

# The SEAS files of 3D models (SEAS BP5 on its coarse 4 km cells): station
# syntax, a station off the contact (on the coarse mesh, before the
# operator is built), two stations with one file name, a profile beyond the
# contact nodes and the creeping node next to them (after the operator's
# set-up, still before the run folder), off-fault stations without all components,
# and all components with antiplane (BP1); a creep face off the contact's
# plane, and a free contact normal that nothing else holds (the body's
# rigid motion across the plane).
check_bp5() { # name, expected word, prm body (appended after the include)
  local name=$1 word=$2 body=$3
  printf 'include %s/prm/seas-bp5-qd.prm\nset Output directory = run-%s\nsubsection Mesh file\nset File = %s/prm/meshes/seas-bp5.msh\nend\nsubsection Mesh\nset Local refinements = 0\nend\n%b\n' \
    "$src" "$name" "$src" "$body" > "$name.prm"
  check_file "$name" "$word"
}
check_bp5 seas-plane-syntax "Plane stations: '1, 2, 3' is not 'x2, x3'" 'subsection Output\nsubsection SEAS\nset Plane stations = 1, 2, 3\nend\nend'
check_bp5 seas-plane-outside "Plane stations: (x2, x3) = (60000, 10000) m lies outside the contact" 'subsection Output\nsubsection SEAS\nset Plane stations = 0, 0; 60e3, 10e3\nend\nend'
check_bp5 seas-plane-names "share the file name fltst_strk+00dp+00" 'subsection Output\nsubsection SEAS\nset Plane stations = 0, 0; 100, 0\nend\nend'
check_bp5 seas-depth-profile "Depth profile: (x2, x3) = (0, 44000) m lies outside the contact" 'subsection Output\nsubsection SEAS\nset Depth profile = 0, 0, 44e3, 1e3\nend\nend'
check_bp5 seas-blkst-components "Observation components = up" 'subsection Mesh file\nset Observation components = up\nend\nsubsection Output\nsubsection SEAS\nset Depth profile = 0, 0, 36e3, 1e3\nend\nend'
check_bp5 creep-off-plane "a creep face (tag 3) is not in the contact's plane" 'subsection Mesh file\nset Boundary roles = 1: contact, 2: free-slip, 3: creep, 4: free, 5: creep, 6: free\nend'
check_bp5 free-normal-unheld "Contact normal = free: no boundary holds the body's motion normal to the contact" 'subsection Mesh file\nset Boundary roles = 1: contact, 2: free, 3: free, 4: free, 5: creep, 6: free\nend'
# A shear stress perturbation (SEAS BP7's nucleation): only with the
# Green's functions, its history a function of t alone and only with it.
check_bp1 perturbation-volume "Shear stress perturbation: needs Solver/Bulk = green-function" 'subsection Mesh file\nsubsection Friction\nset Shear stress perturbation = 1e6\nend\nend\nsubsection Time stepping\nset Integrator = implicit\nend\nsubsection Solver\nset Bulk = volume\nend'
check_bp1 perturbation-history-space "Shear stress perturbation history = exp(-x): must be a function of the time t alone" 'subsection Mesh file\nsubsection Friction\nset Shear stress perturbation = 1e6\nset Shear stress perturbation history = exp(-x)\nend\nend'
check_bp1 perturbation-history-alone "Shear stress perturbation history = t: needs Shear stress perturbation" 'subsection Mesh file\nsubsection Friction\nset Shear stress perturbation history = t\nend\nend'
check_bp1 observation-components-antiplane "Observation components = all: not with Displacement = antiplane" 'subsection Mesh file\nset Observation components = all\nend'

# A pore pressure (SEAS BP6): only with the Green's functions, only with a
# prescribed normal stress below it, a Darcy velocity only with it, the
# SEAS down-dip station names only at positions >= 0.
check_bp6() { # name, expected word, prm body (appended after the include)
  local name=$1 word=$2 body=$3
  printf 'include %s/prm/seas-bp6-qd-a.prm\nset Output directory = run-%s\n%b\n' \
    "$src" "$name" "$body" > "$name.prm"
  check_file "$name" "$word"
}
check_bp6 pore-pressure-volume "Pore pressure: needs Solver/Bulk = green-function" 'subsection Time stepping\nset Integrator = implicit\nend\nsubsection Solver\nset Bulk = volume\nend'
check_bp6 pore-pressure-sigma "Pore pressure = 6e+07" 'subsection Mesh file\nsubsection Friction\nset Pore pressure = 60e6\nend\nend'
check_bp6 pore-pressure-gravity "Pore pressure" 'subsection Mesh file\nsubsection Friction\nset Normal stress =\nend\nend'
check_bp6 pore-pressure-syntax "Friction/Pore pressure" 'subsection Mesh file\nsubsection Friction\nset Pore pressure = 1e6 * tau\nend\nend'
check_bp6 darcy-without-pressure "Darcy velocity" 'subsection Mesh file\nsubsection Friction\nset Pore pressure =\nend\nend'
check_bp6 seas-negative-down-dip "Fault stations: -1500 m is negative" 'subsection Output\nsubsection SEAS\nset Fault station names = down-dip\nend\nend'
check_bp6 seas-origin "Fault stations: 7500 m from the origin 35000" 'subsection Output\nsubsection SEAS\nset Fault station origin = 35e3\nend\nend'
# The pore pressure diffusing from an injection (Pore fluid/Source =
# gaussian, point, well) instead of the expressions: not with them, the
# well only in 3D, the injection node on the mesh, the contact inside the
# fluid domain, positive coefficients, one plane coordinate in 2D.
check_bp6 pore-fluid-expression "given with Pore fluid/Source = point" 'subsection Mesh file\nsubsection Friction\nsubsection Pore fluid\nset Source = point\nend\nend\nend'
check_bp6 pore-fluid-well-2d "Source = well: a Peaceman well needs Dimension = 3" 'subsection Mesh file\nsubsection Friction\nset Pore pressure =\nset Darcy velocity =\nsubsection Pore fluid\nset Half width = 20000\nset Cell size = 50\nset Plane coordinates = -y\nset Source = well\nend\nend\nend'
check_bp6 pore-fluid-odd-cells "Cell size = 8000: 2 x Half width / Cell size = 5 must be an even integer" 'subsection Mesh file\nsubsection Friction\nset Pore pressure =\nset Darcy velocity =\nsubsection Pore fluid\nset Half width = 20000\nset Cell size = 50\nset Plane coordinates = -y\nset Source = point\nset Cell size = 8000\nend\nend\nend'
check_bp6 pore-fluid-outside "Pore fluid/Half width: the contact point (0, -20000) m" 'subsection Mesh file\nsubsection Friction\nset Pore pressure =\nset Darcy velocity =\nsubsection Pore fluid\nset Half width = 20000\nset Cell size = 50\nset Plane coordinates = -y\nset Source = point\nset Half width = 10000\nend\nend\nend'
check_bp6 pore-fluid-porosity "Pore fluid/Porosity = 0: must be > 0" 'subsection Mesh file\nsubsection Friction\nset Pore pressure =\nset Darcy velocity =\nsubsection Pore fluid\nset Half width = 20000\nset Cell size = 50\nset Plane coordinates = -y\nset Source = point\nset Porosity = 0\nend\nend\nend'
check_bp6 pore-fluid-coordinates "Plane coordinates = y; x: must be 1 expression" 'subsection Mesh file\nsubsection Friction\nset Pore pressure =\nset Darcy velocity =\nsubsection Pore fluid\nset Half width = 20000\nset Cell size = 50\nset Plane coordinates = -y\nset Source = point\nset Plane coordinates = y; x\nend\nend\nend'

# missing parameter file
"$exe" no-such-file.prm > /dev/null 2> missing.err
if [ $? -ne 0 ] && [ "$(wc -l < missing.err)" -eq 1 ] && grep -q "no-such-file.prm" missing.err
then n_pass=$((n_pass + 1)); else n_fail=$((n_fail + 1)); echo "FAILED missing file"; fi
echo "missing-file: $(cat missing.err)"

# SEAS BP3's files: the slip's sign and the surface stations' components
check_bp3() { # name, expected word, prm body (appended after the include)
  local name=$1 word=$2 body=$3
  printf 'include %s/prm/seas-bp3-qd.prm\nset Output directory = run-%s\n%b\n' \
    "$src" "$name" "$body" > "$name.prm"
  check_file "$name" "$word"
}
check_bp3 seas-thrust-slip "Thrust slip" 'subsection Output\nsubsection SEAS\nset Thrust slip = sideways\nend\nend'
check_bp3 seas-two-components-mirror "Observation components = all" 'subsection Mesh\nset Local refinements = 0\nend\nsubsection Output\nsubsection SEAS\nset Mirror model = true\nend\nend'

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
