#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Cost of the seismic cycles of an rsfcycle run folder.

Usage: /usr/bin/python3 scripts/cycle_stats.py RUNDIR [--cycles N]

Over the last N complete cycles (default: all between the first and the
last event start of events.csv) it prints the number of cycles, their
mean recurrence time, accepted steps per cycle, wall time per cycle (from
the progress lines of log.txt, interpolated to the event starts), and per
accepted step (one spatial problem with its fixed-point iteration) the
max and mean of the fixed-point iterations, TNNMG iterations and linear
(multigrid) cycles of time-series.csv.
"""
import csv
import os
import re
import sys


def wall_at(progress, t):
    """Wall time [s] at simulated time t, linear between progress lines."""
    for (t0, w0), (t1, w1) in zip(progress, progress[1:]):
        if t0 <= t <= t1:
            return w0 + (w1 - w0) * (t - t0) / max(t1 - t0, 1e-300)
    return None


def main():
    rundir = sys.argv[1]
    n_cycles = (int(sys.argv[sys.argv.index("--cycles") + 1])
                if "--cycles" in sys.argv else None)
    events = list(csv.DictReader(open(os.path.join(rundir, "events.csv"))))
    starts = [float(e["start_s"]) for e in events]
    if len(starts) < 2:
        sys.exit(f"{rundir}: fewer than two events, no complete cycle")
    if n_cycles is not None:
        starts = starts[-(n_cycles + 1):]
    t0, t1 = starts[0], starts[-1]
    rows = [r for r in csv.DictReader(open(os.path.join(rundir,
                                                        "time-series.csv")))
            if t0 < float(r["time_s"]) <= t1]
    progress = []
    pattern = re.compile(r"\*\*\* Step \d+: t = ([0-9.e+-]+) s .*wall "
                         r"(\d+)h(\d+)m(\d+)s")
    for line in open(os.path.join(rundir, "log.txt")):
        m = pattern.search(line)
        if m:
            h, mi, se = (int(m.group(i)) for i in (2, 3, 4))
            progress.append((float(m.group(1)), 3600 * h + 60 * mi + se))
    unknowns = re.search(r"(\d+) unknowns",
                         open(os.path.join(rundir, "log.txt")).read())
    cycles = len(starts) - 1
    print(f"run folder: {rundir}")
    if unknowns:
        print(f"unknowns: {unknowns.group(1)}")
    print(f"events: {len(events)}; cycles measured: {cycles} "
          f"(event starts {t0:g} to {t1:g} s)")
    print(f"mean recurrence time: {(t1 - t0) / cycles:.3f} s")
    print(f"accepted steps per cycle: {len(rows) / cycles:.1f}")
    w0, w1 = wall_at(progress, t0), wall_at(progress, t1)
    if w0 is not None and w1 is not None:
        print(f"wall time per cycle: {(w1 - w0) / cycles / 60:.1f} min")
    for key, label in [("fixed_point_iterations", "fixed-point iterations"),
                       ("tnnmg_iterations", "TNNMG iterations"),
                       ("linear_iterations", "linear cycles")]:
        v = [int(r[key]) for r in rows]
        print(f"{label} per step: max {max(v)}, mean {sum(v) / len(v):.2f}")


if __name__ == "__main__":
    main()
