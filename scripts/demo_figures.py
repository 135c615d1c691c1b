#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The figures README.md quotes of the demo run, from its run folder.

Usage: /usr/bin/python3 scripts/demo_figures.py [RUNDIR] [--plot]

RUNDIR is the folder of `bash quickstart.sh run` (default output-wedge-2d).
Prints, as README.md words them: the mesh, the events (count, first start,
from which event on the recurrence is constant to 0.1 %, median
recurrence, rupture width, peak slip rate, slip and uplift per event at the
observation points, after the first two events), the steps and spatial
problems, the step sizes, the fixed-point iterations, the wall time of the
run (TimerOutput "Total wallclock"), the ranks, and the version line and
date of the run (the first line of log.txt and the folder's time stamp).
With --plot it also writes doc/figures/demo-slip-rate.png and
doc/figures/demo-surface-displacement.png through scripts/plot_wedge.py.
"""
import csv
import datetime
import os
import re
import shutil
import statistics
import subprocess
import sys

TRANSITION = 2  # events left out of the statistics, as summary.txt does


def uplift_per_event(rundir, events, names):
    """Uplift [um] during each event at each observation point."""
    rows = list(csv.DictReader(open(os.path.join(rundir, "time-series.csv"))))
    times = [float(r["time_s"]) for r in rows]

    def at(t, column):  # the first row at or after t
        lo, hi = 0, len(times) - 1
        while lo < hi:
            mid = (lo + hi) // 2
            if times[mid] < t:
                lo = mid + 1
            else:
                hi = mid
        return float(rows[lo][column])

    return {name: [1e6 * (at(float(e["end_s"]), name) -
                          at(float(e["start_s"]), name)) for e in events]
            for name in names}, len(rows)


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    rundir = args[0] if args else "output-wedge-2d"
    log = open(os.path.join(rundir, "log.txt")).read()
    events = list(csv.DictReader(open(os.path.join(rundir, "events.csv"))))
    header = open(os.path.join(rundir, "time-series.csv")).readline()
    names = [c for c in header.strip().split(",") if c.startswith("uplift_")]
    uplift, n_steps = uplift_per_event(rundir, events, names)
    after = events[TRANSITION:]
    rec = [float(e["recurrence_s"]) for e in after]
    median_rec = statistics.median(rec)
    # the first event from which on every recurrence is within 0.1 % of
    # the median
    periodic = next(i for i in range(len(events))
                    if all(abs(float(e["recurrence_s"]) / median_rec - 1)
                           < 1e-3 for e in events[max(i, 1):]))
    v0 = float(re.search(r"set Convergence rate\s*=\s*(\S+)",
                         open(os.path.join(rundir, "parameters.prm")).read())
               .group(1))
    summary = open(os.path.join(rundir, "summary.txt")).read()
    ranks = re.search(r"MPI ranks: (\d+)", log)
    wall = re.search(r"Total wallclock time elapsed since start\s*\|\s*"
                     r"([0-9.e+]+)s", log)
    first_line = log.splitlines()[0]
    stamp = datetime.datetime.fromtimestamp(
        os.path.getmtime(os.path.join(rundir, "summary.txt")))

    def median(column, scale=1.):
        return scale * statistics.median(float(e[column]) for e in after)

    print(f"run folder {rundir}, written {stamp:%Y-%m-%d} by: {first_line}")
    print(f"mesh: {re.search(r'Mesh: (.*)', log).group(1)}; "
          f"{re.search(r'Cell diameters: (.*)', log).group(1)}")
    print(f"{len(events)} events, the first at "
          f"{float(events[0]['start_s']):.1f} s, periodic (to 0.1 %) from "
          f"event {periodic + 1} on; recurrence {median_rec:.3f} s, rupture "
          f"width {median('rupture_width_m'):.3f} m, peak slip rate "
          f"{median('peak_slip_rate_m_per_s', 1e3):.3f} mm/s "
          f"({median('peak_slip_rate_m_per_s') / v0:.0f} v0), slip "
          f"{median('slip_um'):.1f} um, uplift per event "
          + " / ".join(f"{statistics.median(uplift[n][TRANSITION:]):.1f}"
                       for n in names)
          + " um at " + ", ".join(n.split("_")[1] for n in names))
    steps = re.search(r"Spatial problems: (\d+)", summary).group(1)
    sizes = re.search(r"Step size: (.*)", summary).group(1)
    fp = re.search(r"Max fixed-point iterations per step: (\d+)",
                   summary).group(1)
    print(f"{n_steps - 1} steps ({steps} spatial problems), step sizes "
          f"{sizes}, at most {fp} fixed-point iterations per step")
    if wall:
        seconds = float(wall.group(1))
        print(f"wall time {int(seconds // 60)} min {seconds % 60:.0f} s on "
              f"{ranks.group(1) if ranks else 1} MPI rank(s)")
    if "--plot" in sys.argv:
        root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
        out = os.path.join(rundir, "figures")
        subprocess.run([sys.executable, os.path.join(root, "scripts",
                                                     "plot_wedge.py"),
                        rundir, "--out", out], check=True)
        for source, target in [("fig4-slip-rate.png", "demo-slip-rate.png"),
                               ("fig3-surface-displacement.png",
                                "demo-surface-displacement.png")]:
            shutil.copy(os.path.join(out, source),
                        os.path.join(root, "doc", "figures", target))
        print("doc/figures/demo-slip-rate.png, "
              "doc/figures/demo-surface-displacement.png written")


if __name__ == "__main__":
    main()
