# SPDX-License-Identifier: LGPL-2.1-or-later
"""Headless check of an rsfcycle run folder's snapshots with ParaView.

Usage: python3 -m rsfcycle.paraview check RUN|FILE (runs this script as
  xvfb-run -a pvbatch check_pvd.py RUN/solution.pvd or FILE)

Opens the record (solution.pvd or fault.pvd of the VTU snapshots,
solution.xdmf or fault.xdmf of the HDF5 ones), updates it at the last time
step and prints the number of time steps, points and cells, and every point
and cell array with its range (per component; vectors also by magnitude).
Exits with status 1 if one of the fields that rsfcycle writes into that
record is missing. deal.II writes cell-wise vectors such
as material_id as point data constant on each cell (VTU files from DataOut
hold no cell data), so material_id is accepted from either.
"""

import sys

import os

from paraview.simple import PVDReader, XDMFReader

# the fields of the body's record (solution.*) and of the fault's (fault.*)
POINT_ARRAYS = {
    "solution": ["displacement", "velocity", "slip_rate",
                 "log10_slip_rate_over_v0", "state", "friction_coefficient",
                 "shear_traction", "normal_stress"],
    "fault": ["slip_rate_minus_v0", "log10_slip_rate_over_v0", "state",
              "slip_um", "shear_traction", "normal_stress",
              "friction_coefficient"]}
CELL_ARRAYS = {"solution": ["material_id", "mpi_rank"], "fault": []}


def print_arrays(kind, arrays):
    print(f"{kind} arrays:" + ("" if arrays.keys() else " none"))
    for name in arrays.keys():
        array = arrays[name]
        n = array.GetNumberOfComponents()
        ranges = [array.GetRange(c) for c in range(n)]
        if n > 1:
            ranges.append(array.GetRange(-1))
        text = ", ".join(f"[{lo:.6g}, {hi:.6g}]" for lo, hi in ranges)
        suffix = " (components, magnitude)" if n > 1 else ""
        print(f"  {name}: {text}{suffix}")


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    path = sys.argv[1]
    if not os.path.isfile(path):
        print(f"{path}: not found")
        return 2
    stem, extension = os.path.splitext(os.path.basename(path))
    kind = "fault" if stem == "fault" else "solution"
    if extension == ".xdmf":
        reader = XDMFReader(FileNames=[path])
    else:
        reader = PVDReader(FileName=path)
    times = list(reader.TimestepValues)
    last = times[-1] if times else 0.0
    reader.UpdatePipeline(time=last)
    info = reader.GetDataInformation()

    print(f"File: {sys.argv[1]}")
    print(f"Time steps: {len(times)}"
          + (f" (t = {times[0]:g} s to {last:g} s)" if times else ""))
    print(f"At t = {last:g} s: {info.GetNumberOfPoints()} points, "
          f"{info.GetNumberOfCells()} cells")
    print_arrays("Point", reader.PointData)
    print_arrays("Cell", reader.CellData)

    missing = [f"point array {name}" for name in POINT_ARRAYS[kind]
               if name not in reader.PointData.keys()]
    for name in CELL_ARRAYS[kind]:
        if name in reader.CellData.keys():
            continue
        if name in reader.PointData.keys():
            # deal.II 9.4's DataOut has no cell data: it writes a cell
            # vector as point values that are constant on each cell.
            print(f"Note: {name} found as point data, constant per cell")
        else:
            missing.append(f"cell array {name}")
    if missing:
        print("MISSING: " + ", ".join(missing))
        return 1
    print("OK: all expected arrays present")
    return 0


if __name__ == "__main__":
    sys.exit(main())
