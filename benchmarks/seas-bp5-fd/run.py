#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""SEAS BP5-FD: the first event of BP5 with inertia at 2 km and 1 km on 2
ranks, against BP5-QD's first event at the same cells; the rows and
figures of benchmarks/seas-bp5-fd/README.md.

From the repository's root, with the package on the path:

  PYTHONPATH=python /usr/bin/python3 benchmarks/seas-bp5-fd/run.py COMMAND ...

  runs     prm/seas-bp5-fd.prm with Stop after events = 1 and End time =
           1200 s into WORK/fd-2km and fd-1km (Local refinements 1 and
           2), prm/seas-bp5-qd.prm with Stop after events = 1 into
           WORK/qd-first-2km and qd-first-1km, 2 ranks (about 2.5, 6.5
           and a few minutes); --cells and --kinds choose, --hour runs
           the 2 km FD file to its own end into fd-2km-hour
  results  the first events of those folders, their cost, FD - QD at
           each cell size, 1 km against 2 km and the SEAS checker on the
           FD folders into results.csv (the rows fd.* and bp5-fd.*)

WORK is --work (default benchmarks/seas-bp5-fd/runs). An event is max V
>= 1 mm/s in global.dat (rsfcycle.catalog.detect, runs within an hour
joined); the surface slip is the station fltst_strk+00dp+00's; Mw from
global.dat's moment rate integrated over the event.
"""

import json
import os
import re
import resource
import subprocess
import sys

from rsfcycle import bench, results as results_file, run as run_folder, seas
from rsfcycle.peers import hbi

HERE = os.path.dirname(os.path.abspath(__file__))
STATION = "fltst_strk+00dp+00"
MERGE = 3600.0


def pct(x, digits=2):
    return hbi.signed(100 * x, digits)


# BP5-FD's first event and BP5-QD's at the same cells: the shipped files
# with Stop after events = 1; 2 km is Local refinements = 1. QD's event
# ends as FD's does (Event merge time = MERGE). FD ends at FD_END: its
# event is over by about 800 s, and the rest of the hour-long merge
# window (slip rates below 0.2 mm/s at 2 km) would cost more than the
# event, in implicit steps once a trial succeeds (README).
FD_END = 1200.0  # [s]
MODELER = "rsfcycle benchmarks/seas-bp5-fd"
FD_CELLS = {"2km": {"Mesh/Local refinements": 1}, "1km": {}}
FD_KINDS = {"fd": ("prm/seas-bp5-fd.prm", "fd-{}", {"End time": FD_END}),
            "qd": ("prm/seas-bp5-qd.prm", "qd-first-{}",
                   {"Output/Event merge time": MERGE})}
CELL_TEXT = {"2km": "2 km", "1km": "1 km"}


def fd(args):
    """BP5-FD's and BP5-QD's first events into --work (2 ranks)."""
    for cells in args.cells:
        for kind in args.kinds:
            base, name, entries = FD_KINDS[kind]
            folder = os.path.join(args.work, name.format(cells))
            if args.hour and kind == "fd":
                entries, folder = {}, folder + "-hour"
            entries = dict(entries, **FD_CELLS[cells], **{
                "Stop after events": 1, "Output/SEAS/Modeler": MODELER})
            print(f"{folder}: {base} with {entries}", flush=True)
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            try:
                hbi.run_rsfcycle(base, folder, entries, args.ranks, args.binary)
            except subprocess.CalledProcessError as error:
                # stopped (--hour) or failed: its log.txt says which
                print(f"{folder}: exit status {error.returncode}, see its log.txt",
                      flush=True)
                continue
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            # the ranks' CPU time beside run-context.json's commit and load
            path = os.path.join(folder, "run-context.json")
            with open(path, encoding="utf-8") as f:
                context = json.load(f)
            context["cpu_s"] = (after.ru_utime + after.ru_stime - before.ru_utime
                                - before.ru_stime)
            with open(path, "w", encoding="utf-8") as f:
                json.dump(context, f)
            wall = hbi.rsfcycle_times(folder)[0]
            print(f"{folder}: {hbi.duration(wall) if wall else 'no timer table'}, "
                  f"{context['cpu_s']:.0f} s CPU", flush=True)


def log_figures(folder):
    """unknowns, contact nodes, the explicit step [s] and how it was
    chosen (None without explicit steps) of a run folder's log.txt."""
    text = bench.text(os.path.join(folder, "log.txt"))
    mesh = re.search(r"Mesh: \d+ cells, \d+ levels, (\d+) unknowns, (\d+) contact nodes",
                     text)
    step = re.search(r"Explicit step: ([0-9.e+-]+) s, Courant number ([0-9.e+-]+) x the "
                     r"stable step ([0-9.e+-]+) s of ([a-z-]+)", text)
    return (int(mesh.group(1)) if mesh else None, int(mesh.group(2)) if mesh else None,
            float(step.group(1)) if step else None,
            f"Courant number {step.group(2)} of {step.group(4)}'s stable step "
            f"{float(step.group(3)):.4g} s" if step else None)


def step_kinds(folder, has_explicit, start, end):
    """{explicit, implicit, explicit_in_event, implicit_in_event,
    spatial_problems} of a run folder's time-series.csv: a step that
    solved nothing (no fixed-point or TNNMG iteration) is explicit; the
    spatial problems of the implicit steps include their refused tries."""
    import numpy as np
    ts = run_folder.time_series(folder)
    t = ts["time_s"].to_numpy()
    explicit = (ts["fixed_point_iterations"].to_numpy() == 0) & (
        ts["tnnmg_iterations"].to_numpy() == 0) if has_explicit else np.zeros(len(t), bool)
    inside = (t > start) & (t <= end)
    return dict(explicit=int(explicit.sum()), implicit=int((~explicit).sum()),
                implicit_in_event=int((~explicit & inside).sum()),
                explicit_in_event=int((explicit & inside).sum()),
                spatial_problems=int(ts["spatial_problems"].to_numpy()[~explicit].sum()))


def progress(folder):
    """[(t [s], wall [s])] of log.txt's progress lines (one every 10 s of
    wall time)."""
    return [(float(t), 3600 * int(h) + 60 * int(m) + int(sec)) for t, h, m, sec in
            re.findall(r"^\*\*\* Step \d+: t = ([0-9.e+-]+) s .*wall (\d+)h(\d+)m(\d+)s",
                       bench.text(os.path.join(folder, "log.txt")), re.M)]


def wall_at(folder, t):
    """The wall time [s] of the first progress line at or after the
    simulated time t [s], or None."""
    return next((wall for step_t, wall in progress(folder) if step_t >= t), None)


def cpu_time(folder):
    """The ranks' CPU time [s] of a run of `fd` (run-context.json), or None."""
    path = os.path.join(folder, "run-context.json")
    if not os.path.exists(path):
        return None
    with open(path, encoding="utf-8") as f:
        return json.load(f).get("cpu_s")


def first_event(folder):
    """The first event of a run folder (hbi.catalogue) with its run's
    figures: unknowns, contact nodes, explicit step, wall times of the
    run, the time loop and the explicit steps, the step counts."""
    events = hbi.catalogue(folder, STATION, merge=MERGE)
    if not events:
        raise FileNotFoundError(f"{folder}: no finished event in global.dat")
    e = dict(events[0])
    (e["unknowns"], e["contact_nodes"], e["explicit_step"],
     e["explicit_choice"]) = log_figures(folder)
    e["wall"], e["loop"], e["operator"] = hbi.rsfcycle_times(folder)
    e["explicit_wall"] = run_folder.section_time(folder, "Explicit step")
    e["wall_to_end"] = wall_at(folder, e["end"])
    found = re.search(r"\|\s*TNNMG: linear correction\s*\|\s*(\d+)\s*\|\s*([0-9.e+-]+)s",
                      bench.text(os.path.join(folder, "log.txt")))
    e["corrections"] = (int(found.group(1)), float(found.group(2))) if found else None
    e["cpu"] = cpu_time(folder)
    e.update(step_kinds(folder, e["explicit_step"] is not None, e["start"], e["end"]))
    return e


def hour_rows(folder, cells):
    """Rows of FD run in the whole merge window (fd --hour), stopped or
    not: what its steps cost after the event, explicit and implicit."""
    text = bench.text(os.path.join(folder, "log.txt"))
    where = CELL_TEXT[cells]
    e = first_event(folder)
    switch = re.search(r"implicit steps from t = ([0-9.e+-]+) s", text)
    stop = re.search(r"Stopped by signal \d+ at t = ([0-9.e+-]+) s", text)
    end = re.search(r"Stop after events = \d+ reached: the run ends at t = ([0-9.e+-]+) s",
                    text)
    key = f"fd.hour.{cells}."
    rows = []
    if stop:
        rows.append((key + "stopped", f"{float(stop.group(1)):.0f}", "s", f"{where}: "
                     "the run with the hour-long merge window, stopped by SIGTERM at "
                     f"this time (the event ended at {e['end']:.0f} s)"))
    if end:
        rows.append((key + "end", f"{float(end.group(1)):.0f}", "s", f"{where}: the "
                     "run with the hour-long merge window ends itself (Stop after events "
                     f"= 1) at this time, an hour after the event's end ({e['end']:.0f} s)"))
        if e["wall"]:
            rows.append((key + "cost", hbi.duration(e["wall"]), "", f"{where}: the "
                         "whole run with the hour-long merge window on 2 ranks"))
    if e["explicit_wall"] and e["explicit"]:
        ratio = e["explicit_wall"] / (e["explicit"] * e["explicit_step"])
        rows.append((key + "explicit", f"{ratio:.2f}",
                     "x", f"{where}: wall time over simulated time in the explicit "
                     f"steps ({e['explicit']} steps of {e['explicit_step']:.4g} s took "
                     f"{e['explicit_wall']:.0f} s)"))
    if switch:
        t0 = float(switch.group(1))
        after = [(t, w) for t, w in progress(folder) if t >= t0]
        rows.append((key + "switch", f"{t0:.0f}", "s", f"{where}: back to implicit "
                     "steps (the first trial whose error estimate allowed 32 explicit "
                     f"steps, {2 * 16 * e['explicit_step']:.3g} s)"))
        if len(after) > 1 and after[-1][0] > after[0][0]:
            (ta, wa), (tb, wb) = after[0], after[-1]
            rows.append((key + "implicit", f"{(wb - wa) / (tb - ta):.2g}", "x",
                         f"{where}: wall time over simulated time in the implicit "
                         f"steps after the switch ({tb - ta:.0f} s took {wb - wa:.0f} s)"))
    if e["corrections"] and e["wall"]:
        rows.append(correction_row(key, where, e))
    return rows


def correction_row(key, where, e):
    """The row KEY.linear_correction: the wall time of one TNNMG linear
    correction and the share of the run that all took."""
    n, seconds = e["corrections"]
    return (key + "linear_correction", f"{seconds / n:.2f}", "s", f"{where}: wall time "
            f"per TNNMG linear correction ({n} of them, {100 * seconds / e['wall']:.0f} % "
            f"of the run's {e['wall']:.0f} s)")


def fd_context(folder):
    """(context, cores) of an fd run for results.record: the commit of the
    binary (log.txt's first line; the runs of one binary may span several
    commits of the tree), the day and the load when the run started
    (run-context.json)."""
    context, cores = hbi.context_of(folder)
    words = run_folder.version(folder).replace(",", " ").split()
    if "commit" in words:
        commit = words[words.index("commit") + 1]
        context["commit"] = commit[:7] + ("-dirty" if commit.endswith("-dirty") else "")
    return context, cores


def fd_results(args):
    """BP5-FD's first events, FD - QD and 1 km - 2 km into results.csv."""
    found = {}
    for cells in FD_CELLS:
        for kind, (_, name, _) in FD_KINDS.items():
            folder = os.path.join(args.work, name.format(cells))
            if os.path.exists(os.path.join(folder, "summary.txt")):
                found[kind, cells] = folder
    if not any(kind == "fd" for kind, _ in found):
        raise FileNotFoundError(f"{args.work}: no finished fd-2km or fd-1km")
    first = {k: first_event(f) for k, f in found.items()}
    print("   run            start [s]  end [s]  peak [m/s]  slip [m]     Mw  "
          "explicit  implicit  wall")
    for (kind, cells), e in first.items():
        print(f"   {kind}-{cells:4s} {e['start']:14.2f} {e['end']:8.1f} {e['peak']:11.4f} "
              f"{e['slip']:9.4f} {e['mw']:6.3f} {e['explicit']:9d} {e['implicit']:9d}  "
              f"{hbi.duration(e['wall']) if e['wall'] else '-'}")
    for (kind, cells), e in first.items():
        context, cores = fd_context(found[kind, cells])
        where = CELL_TEXT[cells]
        if kind != "fd":
            continue
        problems = seas.check(found[kind, cells])[2]
        for p in problems:
            print(f"   {found[kind, cells]}: {p}")
        key = f"fd.{cells}."
        rows = [
            (key + "unknowns", f"{e['unknowns']:,}", "", f"{where}: unknowns "
             f"({e['contact_nodes']} contact nodes)"),
            (key + "explicit_step", f"{e['explicit_step']:.4g}", "s", f"{where}: the "
             f"explicit step ({e['explicit_choice']})"),
            (key + "peak", f"{e['peak']:.3f}", "m/s", f"{where}: first event's peak "
             "slip rate"),
            (key + "surface_slip", f"{e['slip']:.3f}", "m", f"{where}: first event's "
             f"slip at {STATION}"),
            (key + "mw", f"{e['mw']:.3f}", "", f"{where}: first event's Mw "
             "(global.dat's moment rate over the event)"),
            (key + "duration", f"{e['end'] - e['start']:.1f}", "s", f"{where}: first "
             "event from t = 0 to its end, where max V stops crossing 1 mm/s (BP5-QD's "
             f"at this cell size: {first['qd', cells]['end']:.1f} s)" if ("qd", cells) in
             first else f"{where}: first event from t = 0 to its end, where max V stops "
             "crossing 1 mm/s"),
            (key + "steps", f"{e['explicit']} explicit, {e['implicit']} implicit", "",
             f"{where}: steps of the run ({e['explicit_in_event']} explicit and "
             f"{e['implicit_in_event']} implicit inside the event; the implicit "
             f"ones solved {e['spatial_problems']} spatial problems)"),
            (key + "seas_check", "passes" if not problems else f"{len(problems)} problems",
             "", f"{where}: the SEAS checker (python -m rsfcycle.seas check) on the "
             "run folder"),
        ]
        if e["wall"]:
            rows.append((key + "cost", hbi.duration(e["wall"]), "", f"{where}: the whole "
                         f"run to t = {FD_END:.0f} s on 2 ranks"))
        if e["wall_to_end"]:
            rows.append((key + "cost_event", hbi.duration(e["wall_to_end"]), "",
                         f"{where}: wall time from the start to the event's end "
                         "(the progress line after it)"))
        if e["cpu"]:
            rows.append((key + "cpu", hbi.duration(e["cpu"]), "", f"{where}: CPU time "
                         "of the 2 ranks over the whole run"))
        if e["explicit_wall"] and e["explicit"]:
            rows.append((key + "explicit_cost", f"{e['explicit_wall'] / e['explicit']:.3f}",
                         "s", f"{where}: wall time per explicit step (the timer's "
                         f"Explicit step, {e['explicit_wall']:.0f} s in all)"))
        if e["corrections"] and e["wall"]:
            rows.append(correction_row(key, where, e))
        if e["loop"] and e["explicit_wall"]:
            rows.append((key + "implicit_cost", f"{e['loop'] - e['explicit_wall']:.0f}", "s",
                         f"{where}: the time loop's wall time outside the explicit "
                         "steps (the implicit steps and trials, output)"))
        hbi.record(HERE, rows, context, cores)
        if ("qd", cells) in first:
            q = first["qd", cells]
            rows = [
                (f"fd.qd.{cells}.peak", f"{e['peak'] / q['peak']:.2f}", "x",
                 f"{where}: FD over QD, first event's peak slip rate, "
                 f"{e['peak']:.3f} against {q['peak']:.3f} m/s"),
                (f"fd.qd.{cells}.surface_slip", pct(e["slip"] / q["slip"] - 1, 1), "%",
                 f"{where}: FD against QD, first event's surface slip, "
                 f"{e['slip']:.3f} against {q['slip']:.3f} m"),
                (f"fd.qd.{cells}.mw", f"{e['mw'] - q['mw']:+.3f}", "",
                 f"{where}: FD - QD, first event's Mw, {e['mw']:.3f} against "
                 f"{q['mw']:.3f}"),
            ]
            hbi.record(HERE, rows, context, cores)
    for cells in FD_CELLS:
        folder = os.path.join(args.work, f"fd-{cells}-hour")
        if os.path.exists(os.path.join(folder, "log.txt")):
            # the rows of an earlier hour run (stopped or not) go
            path = os.path.join(HERE, "results.csv")
            kept = {k: r for k, r in results_file.read_results(path).items()
                    if not k.startswith(f"fd.hour.{cells}.")}
            results_file.write_results(path, kept.values())
            hbi.record(HERE, hour_rows(folder, cells), *fd_context(folder))
    if ("fd", "2km") in first and ("fd", "1km") in first:
        a, b = first["fd", "1km"], first["fd", "2km"]
        context, cores = fd_context(found["fd", "1km"])
        rows = [
            ("fd.conv.peak", pct(a["peak"] / b["peak"] - 1, 1), "%", "FD, 1 km against "
             f"2 km, first event's peak slip rate, {a['peak']:.3f} against "
             f"{b['peak']:.3f} m/s"),
            ("fd.conv.surface_slip", pct(a["slip"] / b["slip"] - 1, 1), "%", "FD, 1 km "
             f"against 2 km, surface slip, {a['slip']:.3f} against {b['slip']:.3f} m"),
            ("fd.conv.mw", f"{a['mw'] - b['mw']:+.3f}", "", "FD, 1 km - 2 km, Mw, "
             f"{a['mw']:.3f} against {b['mw']:.3f}"),
        ]
        if ("qd", "2km") in first and ("qd", "1km") in first:
            c, d = first["qd", "1km"], first["qd", "2km"]
            rows += [
                ("fd.conv.qd_peak", pct(c["peak"] / d["peak"] - 1, 1), "%", "QD, 1 km "
                 f"against 2 km, first event's peak slip rate, {c['peak']:.3f} against "
                 f"{d['peak']:.3f} m/s"),
                ("fd.conv.qd_surface_slip", pct(c["slip"] / d["slip"] - 1, 1), "%",
                 f"QD, 1 km against 2 km, surface slip, {c['slip']:.3f} against "
                 f"{d['slip']:.3f} m"),
            ]
        # README.md's SEAS table: BP5-FD's row
        rows += [
            ("bp5-fd.cells", "1", "km", "fault cells (the shipped file; 2 km beside it)"),
            ("bp5-fd.events", "the first", "", "events run (Stop after events = 1, End "
             f"time = {FD_END:.0f} s)"),
            ("bp5-fd.peer", "none; BP5-QD's first event", "", "no peer run: the first "
             "event against BP5-QD's at the same cells, and 1 km against 2 km"),
            ("bp5-fd.recurrence", "first event only; Mw "
             f"{a['mw'] - first['qd', '1km']['mw']:+.3f} from QD"
             if ("qd", "1km") in first else "first event only", "",
             "FD - QD at 1 km, the first event's Mw"),
            ("bp5-fd.peak_slip_rate", f"no peer; {a['peak']:.2f} m/s at 1 km "
             f"({pct(a['peak'] / b['peak'] - 1, 1).replace('-', '−')} % from 2 km)", "",
             "the first event's peak slip rate at 1 km and its change from 2 km"),
        ]
        if a["wall"]:
            rows.append(("bp5-fd.cost", f"{hbi.duration(a['wall'])} to {FD_END:.0f} s",
                         "", f"the 1 km run to t = {FD_END:.0f} s on 2 ranks"))
        hbi.record(HERE, rows, context, cores)


def options(p):
    p.add_argument("--cells", nargs="+", choices=list(FD_CELLS), default=list(FD_CELLS),
                   help="2km (Local refinements = 1), 1km (the shipped files)")
    p.add_argument("--kinds", nargs="+", choices=list(FD_KINDS), default=list(FD_KINDS),
                   help="fd (prm/seas-bp5-fd.prm), qd (prm/seas-bp5-qd.prm)")
    p.add_argument("--hour", action="store_true", help="FD without End time, "
                   "the event merge window's hour after the event included, into "
                   "fd-CELLS-hour (about 5 min at 2 km on 2 ranks: the run ends itself an hour "
                   "with a checkpoint and the timer table)")


def main(argv=None):
    return hbi.driver(__doc__, HERE, "bp5", {"runs": fd, "results": fd_results},
                      {"runs": options}, argv=argv)


if __name__ == "__main__":
    sys.exit(main())
