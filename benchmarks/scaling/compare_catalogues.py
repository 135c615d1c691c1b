#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Compare the event catalogues (events.csv) of runs on different numbers
of MPI ranks against the first: number of events, largest difference of the
event starts [ms], of the peak slip rates and of the slips [%].

Usage: benchmarks/scaling/compare_catalogues.py RUN_DIR_1 RUN_DIR_2 ...
"""
import csv
import os
import sys


def catalogue(run):
    return list(csv.DictReader(open(os.path.join(run, "events.csv"))))


def main():
    runs = sys.argv[1:]
    if runs[:1] in (["-h"], ["--help"]):
        print(__doc__)
        return 0
    if len(runs) < 2:
        sys.exit("compare_catalogues.py: usage: compare_catalogues.py "
                 "RUN_DIR_1 RUN_DIR_2 ...")
    ref = catalogue(runs[0])
    print(f"{runs[0]}: {len(ref)} events")
    ok = True
    for run in runs[1:]:
        other = catalogue(run)
        n = min(len(ref), len(other))
        start = max(abs(float(a["start_s"]) - float(b["start_s"]))
                    for a, b in zip(ref[:n], other[:n]))
        peak = max(abs(float(a["peak_slip_rate_m_per_s"]) /
                       float(b["peak_slip_rate_m_per_s"]) - 1)
                   for a, b in zip(ref[:n], other[:n]))
        slip = max(abs(float(a["slip_um"]) / float(b["slip_um"]) - 1)
                   for a, b in zip(ref[:n], other[:n]))
        good = (len(other) == len(ref) and start <= 1e-3 and peak <= 5e-3
                and slip <= 5e-3)
        ok = ok and good
        print(f"{run}: {len(other)} events, starts within "
              f"{1e3 * start:.3f} ms, peak slip rates within "
              f"{100 * peak:.4f} %, slips within {100 * slip:.4f} % "
              f"({'agree' if good else 'DIFFER'}: same count, 1 ms, 0.5 %)")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
