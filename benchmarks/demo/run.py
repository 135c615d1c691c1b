#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The demo run of README.md: the paper's 2D laboratory wedge
(prm/wedge-2d.prm), its figures and its picture.

Usage (from the repository's root, after the build):
  python3 benchmarks/demo/run.py [--ranks N] [--run-folder DIR] [--no-run]
                                 [--plot]

Runs `mpirun -np N build/rsfcycle --force prm/wedge-2d.prm` (N = 2 by
default; the run folder output-wedge-2d/) unless --no-run, then writes the
figures README.md quotes into benchmarks/demo/results.csv, with the commit
of the binary, the date, the ranks and the machine's load at the start:
the mesh, the events (count, first start, from which event on the
recurrence is constant to 0.1 %, median recurrence, rupture width, peak
slip rate, slip and uplift per event at the observation points, after the
first two events), the steps, the step sizes, the fixed-point iterations
and the wall time (TimerOutput's "Total wallclock"). --plot redraws
doc/figures/demo-slip-rate.png and doc/figures/demo-surface-displacement.png
(scripts/plot_wedge.py).
"""
import argparse
import csv
import os
import re
import shutil
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "python"))
from rsfcycle import results  # noqa: E402

TRANSITION = 2  # events left out of the statistics, as summary.txt does


def uplift_per_event(rundir, events, names):
    """Uplift [um] during each event at each observation point, and the
    number of rows of time-series.csv."""
    with open(os.path.join(rundir, "time-series.csv")) as f:
        rows = list(csv.DictReader(f))
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


def figures(rundir):
    """[(key, value, unit, description)] of a finished demo run folder."""
    def read(name):
        with open(os.path.join(rundir, name)) as f:
            return f.read()

    log, summary, prm = read("log.txt"), read("summary.txt"), \
        read("parameters.prm")
    with open(os.path.join(rundir, "events.csv")) as f:
        events = list(csv.DictReader(f))
    if len(events) <= TRANSITION:
        sys.exit(f"{rundir}: {len(events)} events, too few for the figures")
    header = read("time-series.csv").splitlines()[0]
    names = [c for c in header.split(",") if c.startswith("uplift_")]
    uplift, n_rows = uplift_per_event(rundir, events, names)
    after = events[TRANSITION:]
    median_rec = statistics.median(float(e["recurrence_s"]) for e in after)
    periodic = next(i for i in range(len(events))
                    if all(abs(float(e["recurrence_s"]) / median_rec - 1)
                           < 1e-3 for e in events[max(i, 1):]))
    v0 = float(re.search(r"set Convergence rate\s*=\s*(\S+)", prm).group(1))

    def median(column, scale=1.0):
        return scale * statistics.median(float(e[column]) for e in after)

    mesh = re.search(r"Mesh: (\d+) cells, \d+ levels, (\d+) unknowns, "
                     r"(\d+) contact nodes", log)
    diameters = re.search(r"Cell diameters: ([0-9.e+-]+) m to "
                          r"([0-9.e+-]+) m", log)
    sizes = re.search(r"Step size: ([0-9.e+-]+) s to ([0-9.e+-]+) s",
                      summary)
    wall = float(re.search(r"Total wallclock time elapsed since start\s*\|"
                           r"\s*([0-9.e+]+)s", log).group(1))
    rows = [
        ("cells", f"{int(mesh.group(1)):,}", "", "cells of the mesh"),
        ("unknowns", f"{int(mesh.group(2)):,}", "", "unknowns"),
        ("contact_nodes", mesh.group(3), "", "nodes on the base"),
        ("cell_min", f"{1e3 * float(diameters.group(1)):.1f}", "mm",
         "smallest cell diameter (on the patch)"),
        ("cell_max", f"{1e2 * float(diameters.group(2)):.0f}", "cm",
         "largest cell diameter"),
        ("events", str(len(events)), "", "events in the 1000 s"),
        ("first_event", f"{float(events[0]['start_s']):.1f}", "s",
         "start of the first event"),
        ("periodic_from", str(periodic + 1), "",
         "event from which the recurrence is constant to 0.1 %"),
        ("recurrence", f"{median_rec:.3f}", "s", "recurrence (median)"),
        ("rupture_width", f"{median('rupture_width_m'):.3f}", "m",
         "rupture width (median)"),
        ("peak_slip_rate", f"{median('peak_slip_rate_m_per_s', 1e3):.2f}",
         "mm/s", "peak slip rate (median)"),
        ("peak_over_v0", f"{median('peak_slip_rate_m_per_s') / v0:.0f}",
         "v0", "peak slip rate over the load rate v0"),
        ("slip", f"{median('slip_um'):.1f}", "µm", "slip per event (median)"),
    ]
    for name in names:
        where = re.sub(r"(\d)([a-z])", r"\1 \2", name.split("_")[1])
        rows.append((f"uplift_{name.split('_')[1]}",
                     f"{statistics.median(uplift[name][TRANSITION:]):.1f}",
                     "µm", f"uplift per event at {where} from the trench"))
    steps = int(re.search(r"Steps: (\d+)", summary).group(1))
    rows += [
        ("steps", f"{steps:,}", "", "time steps"),
        ("step_min", sizes.group(1), "s", "smallest step"),
        ("step_max", sizes.group(2), "s", "largest step"),
        ("max_fixed_point", re.search(
            r"Max fixed-point iterations per step: (\d+)", summary).group(1),
         "", "fixed-point iterations per step, at most"),
        ("wall_time", f"{wall / 60:.1f}", "min",
         "wall time of the run (TimerOutput)"),
    ]
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--run-folder", default="output-wedge-2d")
    parser.add_argument("--no-run", action="store_true",
                        help="read an existing run folder")
    parser.add_argument("--plot", action="store_true",
                        help="redraw the demo's figures in doc/figures/")
    args = parser.parse_args()
    exe = os.path.join(ROOT, "build", "rsfcycle")
    context = results.run_context(ROOT)  # the machine's load before the run
    if not args.no_run:
        if not os.path.exists(exe):
            sys.exit(f"{exe}: not built (bash quickstart.sh run builds it)")
        env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        subprocess.run(["mpirun", "-np", str(args.ranks), "--oversubscribe",
                        exe, "--force", os.path.join(ROOT, "prm",
                                                     "wedge-2d.prm")],
                       check=True, env=env)
    version = open(os.path.join(args.run_folder, "log.txt")).readline()
    commit = re.search(r"commit ([0-9a-f]+(?:-dirty)?)", version)
    if commit:
        context["commit"] = commit.group(1)[:7] + (
            "-dirty" if commit.group(1).endswith("-dirty") else "")
    ranks = re.search(r"MPI ranks: (\d+)",
                      open(os.path.join(args.run_folder, "log.txt")).read())
    cores = ranks.group(1) if ranks else str(args.ranks)
    rows = [results.Row(key, value, unit, context["commit"], context["date"],
                        cores, context["load"], description)
            for key, value, unit, description in figures(args.run_folder)
            + [("ranks", cores, "", "MPI ranks of the run")]]
    results.write_results(os.path.join(HERE, "results.csv"), rows)
    for row in rows:
        print(f"{row.description}: {row.text()}")
    if args.plot:
        out = os.path.join(args.run_folder, "figures")
        subprocess.run([sys.executable, os.path.join(ROOT, "scripts",
                                                     "plot_wedge.py"),
                        args.run_folder, "--out", out], check=True)
        for source, target in [("fig4-slip-rate.png", "demo-slip-rate.png"),
                               ("fig3-surface-displacement.png",
                                "demo-surface-displacement.png")]:
            shutil.copy(os.path.join(out, source),
                        os.path.join(ROOT, "doc", "figures", target))


if __name__ == "__main__":
    main()
