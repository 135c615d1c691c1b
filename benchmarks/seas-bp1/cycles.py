#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Cycle by cycle: where in the seismic cycle do rsfcycle runs of BP1-QD
leave a peer's (QDYN's)?

Usage:
  cycles.py --qdyn SERIES.csv --rsfcycle LABEL=RUNDIR [...]
            [--depths 12.5,15] [--lags 20,40,60,66,70,74] [--cycles 6]

For cycle k (from the start of event k to that of event k + 1) it prints
log10 V [m/s] at the fault stations `--depths` [km] `--lags` years after
the start of event k, the peer's first, then every run's. Events are where
the maximum slip rate exceeds 1 mm/s (compare.py's definition). SERIES.csv:
the peer's series (qdyn/run.sh writes it) with the columns t_yr (QDYN's
365-day years), max_slip_rate and V_12p5km, V_15km, ... [m/s]; RUNDIR: an
rsfcycle run folder with the SEAS files global.dat and fltst_dpXXX.
"""
import argparse
import csv
import os

import numpy as np
from compare import QDYN_YEAR, THRESHOLD
from seas_files import YEAR, read_table


def starts(t, v):
    above = v > THRESHOLD
    return t[1:][above[1:] & ~above[:-1]]


def peer(path, depths):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    t = np.array([float(r["t_yr"]) for r in rows]) * QDYN_YEAR
    v = np.array([float(r["max_slip_rate"]) for r in rows])
    stations = {}
    for d in depths:
        name = "V_" + ("%g" % d).replace(".", "p") + "km"
        stations[d] = (t, np.log10([float(r[name]) for r in rows]))
    return starts(t, v), stations


def run(rundir, depths):
    g = read_table(os.path.join(rundir, "global.dat"))
    stations = {}
    for d in depths:
        s = read_table(os.path.join(rundir, "fltst_dp%03d" % round(10 * d)))
        stations[d] = (s[:, 0], s[:, 2])
    return starts(g[:, 0], 10 ** g[:, 1]), stations


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--qdyn", required=True)
    parser.add_argument("--rsfcycle", action="append", default=[])
    parser.add_argument("--depths", default="12.5,15")
    parser.add_argument("--lags", default="20,40,60,66,70,74")
    parser.add_argument("--cycles", type=int, default=6)
    args = parser.parse_args()
    depths = [float(x) for x in args.depths.split(",")]
    lags = [float(x) for x in args.lags.split(",")]
    series = [("QDYN",) + peer(args.qdyn, depths)]
    for item in args.rsfcycle:
        label, rundir = item.split("=", 1)
        series.append((label,) + run(rundir, depths))
    print("log10 V [m/s] at the fault stations, years after each event's "
          "start; columns: " + ", ".join(s[0] for s in series))
    for k in range(args.cycles):
        for d in depths:
            for lag in lags:
                values = []
                for _, ev, stations in series:
                    t, logv = stations[d]
                    at = ev[k] + lag * YEAR if k < len(ev) else np.inf
                    values.append("%8.3f" % np.interp(at, t, logv)
                                  if at <= t[-1] else "       -")
                print("cycle %d  %5.1f km  %5.1f yr  %s"
                      % (k + 1, d, lag, " ".join(values)))


if __name__ == "__main__":
    main()
