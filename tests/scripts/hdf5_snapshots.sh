#!/bin/bash
# SPDX-License-Identifier: LGPL-2.1-or-later
# The HDF5 + XDMF snapshots (Output/Writers = hdf5) of a 2-rank 3D run (the
# coarse 3D wedge of wedge_3d_short, 30 s, snapshots every 10 s), written
# beside the VTU ones: one solution-N.h5 and one fault-N.h5 per snapshot
# whatever the ranks (no per-rank pieces), as many as the VTU snapshots and
# as the XDMF index lists; ParaView's XDMF reader (pvbatch) opens
# solution.xdmf and fault.xdmf and finds every field that the VTU records
# have, with the same ranges of the displacement and the slip rate at the
# last time as the PVD record. A spring-slider asking for hdf5 is refused
# in one line naming the entry, with nothing written.
# Usage: hdf5_snapshots.sh RSFCYCLE SOURCE_DIR WORK_DIR
set -u
exe=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work" || exit 1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fail() { echo "FAILED: $*"; exit 1; }
for tool in xvfb-run pvbatch; do
  command -v $tool > /dev/null ||
    fail "$tool not found (Debian packages paraview python3-paraview xvfb; bash quickstart.sh test installs them)"
done

cat > run.prm <<PRM
include $src/prm/wedge-3d.prm
set End time         = 30
set Output directory = run
subsection Mesh
  set Global refinements = 1
  set Local refinements  = 2
end
subsection Time stepping
  set Controller   = step-doubling
  set Maximum step = 2
end
subsection Wedge
  set Ramp time = 5
end
subsection Output
  set Writers           = time series, events, vtu, hdf5
  set Output interval   = 10
  set Progress interval = 1e9
end
PRM
mpirun --quiet --oversubscribe -np 2 "$exe" run.prm > run.log 2>&1 ||
  { tail -5 run.log; fail "the 2-rank run"; }

n_vtu=$(grep -c "<DataSet" run/solution.pvd)
n_h5=$(ls run/solution/*.h5 | wc -l)
n_fault_h5=$(ls run/fault/*.h5 | wc -l)
n_grids=$(grep -c 'Name="mesh"' run/solution.xdmf)
n_fault_grids=$(grep -c 'Name="mesh"' run/fault.xdmf)
echo "snapshots: $n_vtu VTU, $n_h5 + $n_fault_h5 HDF5 files, $n_grids + $n_fault_grids XDMF grids"
[ "$n_vtu" -ge 4 ] || fail "expected snapshots at 0, 10, 20, 30 s, found $n_vtu"
for n in $n_h5 $n_fault_h5 $n_grids $n_fault_grids; do
  [ "$n" -eq "$n_vtu" ] || fail "HDF5 snapshots and XDMF grids ($n) differ from the VTU ones ($n_vtu)"
done
ls run/solution | grep -q '\.[0-9]\{4\}\.h5$' && fail "per-rank HDF5 pieces"
grep -q 'solution/solution-00000.h5:/nodes' run/solution.xdmf ||
  fail "solution.xdmf does not name solution/solution-00000.h5 relative to the run folder"

check() { # record: pvbatch's report into RECORD.report
  local record=$1
  PYTHONPATH="$src/python" \
    xvfb-run -a pvbatch "$src/python/rsfcycle/pvbatch/check_pvd.py" \
    "run/$record" > "$record.report" 2>&1
  local status=$?
  grep -q "^OK: all expected arrays present" "$record.report" ||
    { cat "$record.report"; fail "$record: ParaView misses a field (status $status)"; }
}
for record in solution.xdmf fault.xdmf solution.pvd fault.pvd; do check $record; done
for field in displacement slip_rate; do
  a=$(grep "^  $field:" solution.pvd.report); b=$(grep "^  $field:" solution.xdmf.report)
  [ -n "$a" ] && [ "$a" = "$b" ] || fail "$field at the last time: VTU '$a', HDF5 '$b'"
  echo "last snapshot, $a (VTU and HDF5)"
done
a=$(grep "^  slip_um:" fault.pvd.report); b=$(grep "^  slip_um:" fault.xdmf.report)
[ -n "$a" ] && [ "$a" = "$b" ] || fail "fault slip_um: VTU '$a', HDF5 '$b'"
echo "fault, $a (VTU and HDF5)"

printf 'include %s/prm/spring-slider.prm\nset Output directory = slider\nsubsection Output\nset Writers = events, hdf5\nend\n' \
  "$src" > slider.prm
"$exe" slider.prm > slider.out 2> slider.err && fail "the spring-slider with hdf5 ran"
[ "$(grep -c . slider.err)" -eq 1 ] && grep -q "Output/Writers = hdf5" slider.err &&
  [ ! -e slider ] || { cat slider.err; fail "the spring-slider's refusal"; }
echo "spring-slider: $(cat slider.err)"
echo "hdf5 snapshots: OK"
