#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Converts tandem's BP3-QD output (run.sh) to the files compare.py reads.

    tandem2seas.py RUN

RUN holds tandem's CSV output: global_.csv ("Time","VMax"),
fltst_dpXXX.csv ("Time","state","slip0","traction0","slip-rate0",
"normal-stress"; traction negative for thrust, normal stress positive in
compression) and srfst_fn±08.csv ("Time","u0","u1"; y up). Writes, in RUN:

  global.dat              t, log10 max slip rate [m/s]
  fltst_dpXXX             t, slip [m], log10 slip rate, shear stress
                          (thrust positive), normal stress [MPa]
                          (and fltst_dpXXX.dat, the same, HBI's name)
  srfst_fn±08             t, u_x, u_down [m] (rsfcycle's layout)
  srfst_x±08.dat          t, u_x, u_up [m] (HBI's layout)

so that `compare.py RUN HBI_RUN` and `compare.py RSFCYCLE_RUN RUN` both
work. Works on a run that is still going (the files are read as they are).
Signs stay thrust-positive, as the benchmark's and HBI's files: tandem's
slip0 and slip-rate0 are positive in thrust (its reverse scenario starts at
slip-rate0 = +V_p), its traction0 is the negative of the shear stress.
"""
import glob
import os
import sys

import numpy as np


def table(path):
    """The numeric rows of a tandem CSV file (a '#' title, a quoted header).

    A run continued from a checkpoint (run.sh's RESUME=1) appends rows from
    the checkpoint's time on, after the rows the interrupted run wrote past
    it: where the time goes back, the rows at and after the new row's time
    are dropped, so the continued run's rows are the ones kept."""
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or line.startswith('"'):
                continue
            try:
                row = [float(x) for x in line.split(",")]
            except ValueError:
                continue  # a row cut by a run still writing
            while rows and rows[-1][0] >= row[0]:
                rows.pop()
            rows.append(row)
    return np.array(rows)


def write(path, columns, header):
    np.savetxt(path, np.column_stack(columns), fmt="%.14e", header=header)


def main():
    if len(sys.argv) != 2 or sys.argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(sys.argv) == 2 else 2
    run = sys.argv[1]
    g = table(f"{run}/global_.csv")
    write(f"{run}/global.dat", [g[:, 0], np.log10(g[:, 1])],
          "t [s], log10 max slip rate [m/s] (tandem, converted)")
    for path in sorted(glob.glob(f"{run}/fltst_dp*.csv")):
        name = os.path.basename(path)[:-4]
        s = table(path)
        cols = [s[:, 0], s[:, 2],
                np.log10(np.maximum(np.abs(s[:, 4]), 1e-300)),
                -s[:, 3], s[:, 5]]
        header = ("t [s], slip [m], log10 slip rate [m/s], shear stress "
                  "[MPa], normal stress [MPa] (tandem, converted)")
        write(f"{run}/{name}", cols, header)
        write(f"{run}/{name}.dat", cols, header)
    for x in ("+", "-"):
        u = table(f"{run}/srfst_fn{x}08.csv")
        write(f"{run}/srfst_fn{x}08", [u[:, 0], u[:, 1], -u[:, 2]],
              "t [s], u_x [m], u_down [m] (tandem, converted)")
        write(f"{run}/srfst_x{x}08.dat", [u[:, 0], u[:, 1], u[:, 2]],
              "t [s], u_x [m], u_up [m] (tandem, converted)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
