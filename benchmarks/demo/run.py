#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The demo run of README.md: the paper's 2D laboratory wedge
(prm/wedge-2d.prm, 1000 s), its figures and its pictures.

Stages (from the repository's root, PYTHONPATH=python /usr/bin/python3
benchmarks/demo/run.py STAGE ...):

  run [--ranks N]  prm/wedge-2d.prm on N MPI ranks (default 2) into
                   WORK/wedge-2d (about 5 minutes on 2 idle cores), then
                   `figures` and `plot` of it
  figures [RUN]    the figures README.md quotes, from a finished run folder,
                   into benchmarks/demo/results.csv with the commit, date,
                   ranks and load that `run` saved before the run
                   (run-context.json; else the commit and ranks of
                   log.txt, no load): the mesh, the events (count, first start, the
                   event from which the recurrence is constant to 0.1 %,
                   medians of recurrence, rupture width, peak slip rate,
                   slip and uplift per event after the first two events),
                   the steps, step sizes, fixed-point iterations and wall
                   time (TimerOutput's total)
  plot [RUN]       doc/figures/demo-slip-rate.png and
                   demo-surface-displacement.png (the paper's figures 4
                   and 3 of rsfcycle.plot)

RUN defaults to WORK/wedge-2d when it holds a finished run, else to
output-wedge-2d (what `bash quickstart.sh run` writes).
"""
import os
import re
import shutil
import statistics
import sys

from rsfcycle import bench, events, plot
from rsfcycle import run as reader

NAME = "demo"
HERE = bench.folder(NAME)
TRANSITION = 2  # events left out of the statistics, as summary.txt does


def run_folder(run, work):
    """The run folder a stage reads: the one given, WORK/wedge-2d if it is
    finished, else output-wedge-2d."""
    if run:
        return run
    ours = os.path.join(work, "wedge-2d")
    if os.path.exists(os.path.join(ours, "summary.txt")):
        return ours
    return os.path.join(bench.ROOT, "output-wedge-2d")


def figures_of(folder):
    """[(key, value, unit, description)] of a finished demo run folder."""
    table = reader.events(folder)
    if len(table) <= TRANSITION:
        sys.exit(f"{folder}: {len(table)} events, too few for the figures")
    series = reader.time_series(folder)
    summary = reader.summary(folder)
    log = bench.text(os.path.join(folder, "log.txt"))
    mesh = bench.mesh(log)
    v0 = float(reader.parameters(folder)["Wedge/Convergence rate"])
    after = table.iloc[TRANSITION:]
    recurrence = statistics.median(after["recurrence_s"])
    ratios = (table["recurrence_s"] / recurrence - 1).abs().tolist()
    periodic = next(i for i in range(len(table))
                    if all(r < 1e-3 for r in ratios[max(i, 1):]))

    def median(column, scale=1.0):
        return scale * statistics.median(after[column])
    rows = [
        ("cells", f"{mesh['cells']:,}", "", "cells of the mesh"),
        ("unknowns", f"{mesh['unknowns']:,}", "", "unknowns"),
        ("contact_nodes", str(mesh["contact_nodes"]), "",
         "nodes on the base"),
        ("cell_min", f"{1e3 * mesh['cell_min']:.1f}", "mm",
         "smallest cell diameter (on the patch)"),
        ("cell_max", f"{1e2 * mesh['cell_max']:.0f}", "cm",
         "largest cell diameter"),
        ("events", str(len(table)), "", "events in the 1000 s"),
        ("first_event", f"{table['start_s'].iloc[0]:.1f}", "s",
         "start of the first event"),
        ("periodic_from", str(periodic + 1), "",
         "event from which the recurrence is constant to 0.1 %"),
        ("recurrence", f"{recurrence:.3f}", "s", "recurrence (median)"),
        ("rupture_width", f"{median('rupture_width_m'):.3f}", "m",
         "rupture width (median)"),
        ("peak_slip_rate", f"{median('peak_slip_rate_m_per_s', 1e3):.2f}",
         "mm/s", "peak slip rate (median)"),
        ("peak_over_v0", f"{median('peak_slip_rate_m_per_s') / v0:.0f}",
         "v0", "peak slip rate over the load rate v0"),
        ("slip", f"{median('slip_um'):.1f}", "µm", "slip per event (median)"),
    ]
    for column in events.uplift_columns(series.columns):
        where = column.split("_")[1]
        jump = events.jumps(series["time_s"], series[column],
                            after["start_s"], after["end_s"])
        rows.append((f"uplift_{where}", f"{1e6 * statistics.median(jump):.1f}",
                     "µm", "uplift per event at "
                     + re.sub(r"(\d)([a-z])", r"\1 \2", where)
                     + " from the trench"))
    rows += [
        ("steps", f"{summary['steps']:,}", "", "time steps"),
        ("step_min", f"{summary['min_step']:g}", "s", "smallest step"),
        ("step_max", f"{summary['max_step']:g}", "s", "largest step"),
        ("max_fixed_point", str(summary["max_fixed_point"]), "",
         "fixed-point iterations per step, at most"),
        ("wall_time", f"{reader.wall_time(folder) / 60:.1f}", "min",
         "wall time of the run (TimerOutput)"),
    ]
    return rows


def figures(run: "?" = None, work=""):
    """results.csv from a finished run folder.

    run: the run folder (default: WORK/wedge-2d, else output-wedge-2d)
    """
    folder = run_folder(run, work)
    context, cores = bench.context_of(folder)
    rows = figures_of(folder) + [("ranks", cores, "", "MPI ranks of the run")]
    bench.record(NAME, rows, cores, context)
    for key, value, unit, description in rows:
        print(f"{description}: {value} {unit}".rstrip())


def plot_(run: "?" = None, work=""):
    """The demo's pictures in doc/figures (rsfcycle.plot's figures 4, 3).

    run: the run folder (default: WORK/wedge-2d, else output-wedge-2d)
    """
    folder = run_folder(run, work)
    out = os.path.join(folder, "figures")
    plot.figures(folder, out)
    for source, target in [("fig4-slip-rate.png", "demo-slip-rate.png"),
                           ("fig3-surface-displacement.png",
                            "demo-surface-displacement.png")]:
        shutil.copy(os.path.join(out, source),
                    os.path.join(bench.ROOT, "doc", "figures", target))
        print("copied to doc/figures/" + target)


def run_(ranks=2, build="", work=""):
    """Run the demo on N ranks into WORK/wedge-2d, then figures and plot.

    ranks: MPI ranks
    """
    exe = bench.executable(build)
    out = os.path.join(bench.work(work), "wedge-2d")
    print(f"running prm/wedge-2d.prm on {ranks} ranks into {out} ...",
          flush=True)
    bench.run_variant(exe, os.path.join(bench.ROOT, "prm", "wedge-2d.prm"),
                      out, ranks=ranks)
    figures(out, work)
    plot_(out, work)


if __name__ == "__main__":
    raise SystemExit(bench.cli(__doc__, NAME, [run_, figures, plot_]))
