#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""SEAS BP3-QD and BP3-FD: rsfcycle's runs, their comparison with the peers
HBI and tandem, and the figures of benchmarks/seas-bp3/README.md.

From the repository's root, with the package on the path:

  PYTHONPATH=python /usr/bin/python3 benchmarks/seas-bp3/run.py COMMAND ...

  runs     write rsfcycle's BP3 variants (dip 30/60/90, thrust/normal,
           cells, far field, BP3-QD or BP3-FD) into --work and run them
           (build/rsfcycle); 1500 years at 25 m took 13.6 - 34 min each on
           one shared core (results.csv)
  tables   the event sequences of run folders side by side, then each run
           paired event by event with the first (start, interval, peak
           slip rate, slip at the surface, surface jumps at +-8 km, normal
           stress change)
  figures  the maximum slip rate and the surface station's slip of run
           folders against time, into figures/
  results  the README's rows of results.csv from an rsfcycle run and the
           peers' (rsfcycle.results.record); --dry-run prints them
  equal    the cost at equal accuracy: rsfcycle at its shipped step
           tolerance and 3 and 10 times looser (one rank), HBI at eps_r
           1e-6, 1e-5, 1e-4 (one core), side by side with --run into
           WORK/equal; each code's cheapest run whose catalogue is unchanged
           (rsfcycle.equal), the ratio of the costs into results.csv
  fd       the bp3-fd.* rows: a BP3-FD run's events, its first against
           BP3-QD's and coarser and finer BP3-FD runs' (--dry-run prints them)
  schur    the direct correction's set-up (the contact dofs' Schur
           complement) against a baseline binary: BP3-FD's first 2e5 s at
           100 and 50 m (--cells), wall time and peak memory
  tandem   run tandem on BP3-QD (tandem/run.sh: builds it under
           TANDEM_PREFIX once, about 25 min, then meshes, runs, converts)

A run folder is NAME=FOLDER (NAME labels it): rsfcycle's (time-series.csv
and the SEAS files fltst_dpXXX, srfst_fn+08, srfst_fn-08), HBI's
(python3 -m rsfcycle.peers.hbi run bp3: global.dat, fltst_dpXXX.dat,
srfst_x+08.dat) or tandem's
(tandem/run.sh: global.dat, fltst_dpXXX, srfst_fn+08). The maximum slip
rate comes from time-series.csv, else global.dat, else the second column
of slip.dat. An event is where it exceeds 1 mm/s; a rise within 60 s of
an event's end belongs to it; an event the run ended in is left out.
Years are of 365 days, as prm/seas-bp3-qd.prm's End time.
"""

import argparse
import csv
import datetime
import math
import os
import subprocess
import sys

import numpy as np

from rsfcycle import bench, catalog, prm, results, run, seas
from rsfcycle.peers import hbi

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
YEAR = 3.1536e7  # 365 days: BP3's year, prm/seas-bp3-qd.prm's End time
THRESHOLD = 1e-3  # m/s, the SEAS event threshold
MERGE = 60.0  # s
FD_MERGE = 3600.0  # s: prm/seas-bp3-fd.prm's Event merge time
FRONT = 4.0  # s: the rupture front at a fault station, before later pulses
FRONT_ONSET = 0.01  # m/s: the slip rate that marks the front's arrival
SPONGE_WINDOW = 100.0  # s: the surface slip compared with and without it
SURFACE_SLIP = 0.01  # m: an event that slips the surface by more ruptures it
COARSE = 800.0  # m: the fault's cells of prm/meshes/seas-bp3-*.msh
FAR_FIELD = {"g0": 0, "g1": 1, "g2": 2}  # Mesh/Global refinements
# sin(dip) as prm/seas-bp3-qd.prm writes it in x_d = -y / sin(dip)
SIN = {30: "0.5", 60: "0.8660254037844386", 90: "1"}


# ---------------------------------------------------------------- reading

def max_slip_rate(folder):
    """(t [s], maximum slip rate [m/s]) of any code's run folder."""
    if os.path.exists(os.path.join(folder, "time-series.csv")):
        ts = run.time_series(folder)
        return (ts["time_s"].to_numpy(),
                ts["max_slip_rate_m_per_s"].to_numpy())
    path = os.path.join(folder, "global.dat")
    if os.path.exists(path):
        rows = seas.table(path)[1]
        return rows[:, 0], 10 ** rows[:, 1]
    path = os.path.join(folder, "slip.dat")
    if os.path.exists(path):
        _, t, log10_v, _ = seas.profile(path)
        return t, 10 ** log10_v
    sys.exit(f"{folder}: no time-series.csv, global.dat or slip.dat")


def station(folder, label):
    """Rows (t, slip, log10 V, shear stress, normal stress, ...) of the
    fault station `label` (down dip in 100 m, '000'), or None."""
    for name in (f"fltst_dp{label}", f"fltst_dp{label}.dat"):
        path = os.path.join(folder, name)
        if os.path.exists(path):
            return seas.table(path)[1]
    return None


def surface(folder, x):
    """Rows (t, u_x, u_down) of the surface station at x = '+08' or '-08'
    km, or None (HBI's srfst_x+08.dat has u_up)."""
    path = os.path.join(folder, f"srfst_fn{x}")
    if os.path.exists(path):
        return seas.table(path)[1][:, :3]
    path = os.path.join(folder, f"srfst_x{x}.dat")
    if os.path.exists(path):
        rows = seas.table(path)[1][:, :3].copy()
        rows[:, 2] *= -1
        return rows
    return None


def at(rows, t, column):
    """A column of rows interpolated linearly at time t."""
    return float(np.interp(t, rows[:, 0], rows[:, column]))


def deep_figures(rows, event):
    """A fault station's figures over an event: (peak slip rate [m/s],
    slip [m], and both over the rupture front: the FRONT seconds after
    its slip rate first exceeds FRONT_ONSET)."""
    inside = (rows[:, 0] >= event.start - 1) & (rows[:, 0] <= event.end)
    t, v = rows[inside, 0], 10 ** rows[inside, 2]
    onset = t[np.argmax(v > FRONT_ONSET)]
    front = (t >= onset) & (t <= onset + FRONT)
    return (float(v.max()), change(rows, event, 1), float(v[front].max()),
            at(rows, onset + FRONT, 1) - at(rows, onset, 1))


def change(rows, event, column):
    """A column's change over an event (from 1 s before its start)."""
    return at(rows, event.end, column) - at(rows, event.start - 1, column)


class Run:
    """A run folder's events and stations."""

    def __init__(self, name, folder, until=math.inf, merge=MERGE):
        self.name, self.folder = name, folder
        self.t, self.v = t, v = max_slip_rate(folder)
        self.t_last = t[-1]
        self.events = [e for e in catalog.detect(t, v, THRESHOLD, merge)
                       if e.start < until]
        self.top = station(folder, "000")
        self.deep = station(folder, "100")
        self.surface = {x: surface(folder, x) for x in ("+08", "-08")}
        for e in self.events:
            e.jump = change(self.top, e, 1) if self.top is not None else None


def named(items):
    """[(name, folder)] of NAME=FOLDER arguments (a bare FOLDER is named
    after its last component)."""
    runs = []
    for item in items:
        name, sep, folder = item.partition("=")
        if not sep:
            name, folder = os.path.basename(os.path.normpath(item)), item
        if not os.path.isdir(folder):
            sys.exit(f"{folder}: no such run folder")
        runs.append((name, folder))
    return runs


# -------------------------------------------------------------- formatting

def signed(x, digits=2):
    """+0.13, −0.21 (a minus sign, not a hyphen)."""
    return f"{x:+.{digits}f}".replace("-", "\u2212")


def spread(values, digits=2, listed=4):
    """Up to `listed` values one by one, more as 'lowest … highest'."""
    if len(values) <= listed:
        return ", ".join(signed(v, digits) for v in values)
    return f"{signed(min(values), digits)} \u2026 {signed(max(values), digits)}"


def percent(a, b):
    return 100 * (a / b - 1)


# ------------------------------------------------------------------ tables

def sequence_table(runs):
    """The events of each run side by side (not paired)."""
    lines = ["| # | " + " | ".join(
        f"{r.name} start [yr] | interval | peak [m/s] | slip 0 km [m]"
        for r in runs) + " |", "|---|" + "---|---|---|---|" * len(runs)]
    for k in range(max(len(r.events) for r in runs)):
        cells = [str(k + 1)]
        for r in runs:
            if k >= len(r.events):
                cells += [""] * 4
                continue
            e = r.events[k]
            interval = (e.start - r.events[k - 1].start) / YEAR if k else None
            cells += [f"{e.start / YEAR:.2f}",
                      f"{interval:.2f}" if interval else "\u2014",
                      f"{e.peak:.3f}",
                      f"{e.jump:.3f}" if e.jump is not None else "\u2014"]
        lines.append("| " + " | ".join(cells) + " |")
    ends = ", ".join(f"{r.name} to {r.t_last / YEAR:.0f} yr" for r in runs)
    return "\n".join(lines) + f"\n\n({ends})\n"


def pairs(ours, peer, events=None):
    """catalog.compare of two runs (the first `events`), years of 365 d;
    the slip at the surface compared where the peer's exceeds 0.1 m (a
    partial rupture leaves the surface station nearly still)."""
    rows = catalog.compare(ours.events[:events], peer.events[:events])
    for row, b in zip(rows, peer.events):
        row["start_yr"] *= catalog.YEAR / YEAR
        row["peer_start_yr"] *= catalog.YEAR / YEAR
        if b.jump is None or abs(b.jump) <= 0.1:
            row["jump"] = None
    return rows


def surface_changes(ours, peer, events=None):
    """Per paired event: (index, [(label, ours, peer)] of the surface
    jumps [m] and the normal stress changes [MPa])."""
    out = []
    n = min(len(ours.events), len(peer.events), events or math.inf)
    for k in range(n):
        a, b = ours.events[k], peer.events[k]
        found = []
        for x in ("+08", "-08"):
            if ours.surface[x] is None or peer.surface[x] is None:
                continue
            for column, label in ((1, "u_x"), (2, "u_down")):
                found.append((f"{x} km {label} [m]",
                              change(ours.surface[x], a, column),
                              change(peer.surface[x], b, column)))
        for rows_a, rows_b, label in ((ours.top, peer.top, "0 km"),
                                      (ours.deep, peer.deep, "10 km")):
            if rows_a is not None and rows_b is not None:
                found.append((f"σn {label} [MPa]", change(rows_a, a, 4),
                              change(rows_b, b, 4)))
        out.append((k + 1, found))
    return out


def tables(args):
    """The `tables` command."""
    runs = [Run(n, f, args.until * YEAR) for n, f in named(args.runs)]
    print(sequence_table(runs))
    ours = runs[0]
    for peer in runs[1:]:
        print(f"\n{ours.name} against {peer.name} (relative differences; "
              "slip: at the surface station)\n")
        print(catalog.markdown(pairs(ours, peer, args.events), ours.name,
                               peer.name))
        changes = surface_changes(ours, peer, args.events)
        if changes and changes[0][1]:
            labels = [c[0] for c in changes[0][1]]
            print(f"changes over each event, {ours.name} / {peer.name}\n")
            print("| # | " + " | ".join(labels) + " |")
            print("|---|" + "---|" * len(labels))
            for k, found in changes:
                print(f"| {k} | " + " | ".join(
                    f"{a:+.3f} / {b:+.3f}" for _, a, b in found) + " |")
            print()
    return 0


# ----------------------------------------------------------------- figures

def figures(args):
    """The `figures` command."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    runs = [Run(n, f, args.until * YEAR) for n, f in named(args.runs)]
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    for r in runs:
        keep = r.t < args.until * YEAR
        top.semilogy(r.t[keep] / YEAR, r.v[keep], lw=0.8, label=r.name)
        if r.top is not None:
            keep = r.top[:, 0] < args.until * YEAR
            bottom.plot(r.top[keep, 0] / YEAR, r.top[keep, 1], lw=0.8,
                        label=r.name)
    top.axhline(THRESHOLD, color="0.6", lw=0.5, ls="--")
    top.set_ylabel("max slip rate [m/s]")
    bottom.set_ylabel("slip at 0 km [m]")
    bottom.set_xlabel("time [yr]")
    top.legend(loc="lower right", fontsize=8)
    if args.title:
        top.set_title(args.title)
    fig.tight_layout()
    out = args.output or os.path.join(HERE, "figures", "sequence.png")
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    fig.savefig(out, dpi=130)
    plt.close(fig)
    print("wrote", out)
    return 0


# ----------------------------------------------------------------- results

def run_of(folder, cores, load=None):
    """(context, cores) of an rsfcycle run folder for results.record
    (rsfcycle.bench.context_of: what `runs` saved before the run, else its
    log.txt), the load replaced by `load` if given."""
    context, saved = bench.context_of(folder)
    if load is not None:
        context["load"] = load
    return context, saved if os.path.exists(
        os.path.join(folder, "run-context.json")) else cores


def element_size(folder):
    """The element size [m] of a run's SEAS headers, or None."""
    path = os.path.join(folder, "fltst_dp000")
    if not os.path.exists(path):
        return None
    text = seas.SeasFile(path).keys.get("element_size", "").split()
    return float(text[0]) if text else None


def far_field(folder):
    """g0, g1 or g2 (Mesh/Global refinements of parameters.prm), or None."""
    try:
        value = run.parameters(folder).get("Mesh/Global refinements")
    except FileNotFoundError:
        return None
    return f"g{value.strip()}" if value else None


def result_rows(args):
    """[(key, value, unit, description, context, cores)] of the `results`
    command."""
    rows = []
    cells = element_size(args.rsf)
    case = f"{args.dip}° {args.sense}"
    if cells and cells != 25:
        case += f", {cells:g} m"
    far = far_field(args.rsf)
    if far not in (None, "g1"):
        case += f" (far field {far})"
    prefix = (f"d{args.dip}-{args.sense}" if args.dip == 60 else
              f"dips.{args.dip}-{args.sense}")
    ours = Run("rsfcycle", args.rsf)
    context, cores = run_of(args.rsf, args.cores, args.load)

    def add(key, value, unit, description, ctx=context, n=cores):
        rows.append((key, value, unit, description, ctx, n))

    wall = run.wall_time(args.rsf)
    years = ours.t_last / YEAR
    if wall:
        add(f"{prefix}.cost", f"{wall / 60:.1f}", "min",
            f"{case}: {years:.0f} years, whole run")
    if args.hbi:
        peer = Run("HBI", args.hbi)
        compared = pairs(ours, peer, args.events)
        n = len(compared)
        counts = (f"{len(ours.events)} events in both"
                  if len(ours.events) == len(peer.events) else
                  f"{len(ours.events)} and {len(peer.events)} events")
        which = f"events 1–{n}" if args.events else f"all {n} events"
        starts = [100 * r["start"] for r in compared]
        add(f"{prefix}.starts", spread(starts), "%",
            f"{case}: event starts, {which} ({counts})")
        intervals = [100 * r["interval"] for r in compared
                     if r["interval"] is not None]
        if intervals:
            add(f"{prefix}.intervals", spread(intervals), "%",
                f"{case}: intervals")
        peaks = [100 * r["peak"] for r in compared]
        add(f"{prefix}.peaks", spread(peaks, 1), "%",
            f"{case}: peak slip rate, {which}")
        jumps = [percent(a, b) for _, found in
                 surface_changes(ours, peer, args.events)
                 for label, a, b in found
                 if "km u_" in label and abs(b) > 0.1]
        if jumps:
            add(f"{prefix}.surface_jumps", spread(jumps, 2, 0), "%",
                f"{case}: surface jumps at ±8 km, {which}")
        k = args.recurrence_from - 1
        mine = catalog.intervals(ours.events)[k:]
        theirs = catalog.intervals(peer.events)[k:]
        recurrence = None
        if mine and theirs:
            recurrence = percent(np.mean(mine), np.mean(theirs))
            add(f"{prefix}.recurrence", signed(recurrence, 1), "%",
                f"{case}: mean recurrence from event {k + 1}, "
                f"{np.mean(mine) / YEAR:.2f} against "
                f"{np.mean(theirs) / YEAR:.2f} yr")
        if args.seas_table:
            add("bp3-qd.cells", f"{cells:g}" if cells else "?", "m",
                "BP3-QD: fault cells")
            add("bp3-qd.events", f"{len(ours.events)} in {years:.0f} yr", "",
                f"BP3-QD: events of the {case} run")
            if wall:
                add("bp3-qd.cost", f"{wall / 60:.0f}", "min",
                    f"BP3-QD: {case}, {years:.0f} years, whole run, "
                    "operator included")
            add("bp3-qd.peer", f"HBI at {args.peer_cells or cells:g} m", "",
                "BP3-QD: the peer")
            if recurrence is not None:
                add("bp3-qd.recurrence", signed(recurrence, 1), "%",
                    f"BP3-QD: mean recurrence, {case}, from event {k + 1}")
            add("bp3-qd.peak_slip_rate", spread(peaks, 1), "%",
                f"BP3-QD: peak slip rate, {case}, {which}")
    if args.tandem:
        other = Run("tandem", args.tandem)
        now = results.run_context(ROOT)
        stamp = os.path.getmtime(os.path.join(args.tandem, "global.dat"))
        now["date"] = datetime.date.fromtimestamp(stamp).isoformat()
        others = ", ".join(f"{r.name} {r.events[0].start / YEAR:.2f}"
                           for r in [ours] + ([peer] if args.hbi else [])
                           if r.events)
        if other.events:
            first = other.events[0]
            add("tandem.first_event", f"{first.start / YEAR:.2f}", "yr",
                f"tandem: first event's start ({others})", now, 1)
            peaks = ", ".join(f"{r.name} {r.events[0].peak:.3f}"
                              for r in [ours] + ([peer] if args.hbi else [])
                              if r.events)
            add("tandem.first_peak", f"{first.peak:.3f}", "m/s",
                f"tandem: first event's peak slip rate ({peaks})", now, 1)
        add("tandem.reached", f"{other.t_last / YEAR:.0f}", "yr",
            f"tandem: where the run stands ({len(other.events)} events)",
            now, 1)
    return rows


def write_rows(rows, dry_run):
    """Rows (key, value, unit, description, context, cores) into
    results.csv, or printed as CSV with dry_run."""
    out = csv.writer(sys.stdout, lineterminator="\n")
    for key, value, unit, description, context, cores in rows:
        if dry_run:
            out.writerow([key, value, unit, context["commit"],
                          context["date"], cores, context["load"],
                          description])
        else:
            results.record(HERE, key, value, unit, description, cores,
                           context)
    if not dry_run:
        print(f"{len(rows)} rows written to {os.path.join(HERE, 'results.csv')}"
              "; refresh the README: PYTHONPATH=python python3 -m "
              "rsfcycle.results write benchmarks/seas-bp3")
    return 0


def results_command(args):
    """The `results` command."""
    return write_rows(result_rows(args), args.dry_run)


def fd_rows(args):
    """[(key, value, unit, description, context, cores)] of the `fd`
    command: the BP3-FD run's events (merged within FD_MERGE), each
    ended before the run, against BP3-QD's first event and a coarser and
    a finer BP3-FD run's."""
    fd = Run("rsfcycle", args.fd, merge=FD_MERGE)
    fd.events = [e for e in fd.events if e.end < fd.t_last - FD_MERGE]
    if not fd.events:
        sys.exit(f"{args.fd}: no event has ended")
    cells = element_size(args.fd) or 0
    context, cores = run_of(args.fd, args.cores, args.load)
    rows = []

    def add(key, value, unit, description, ctx=context):
        rows.append((key, value, unit, description, ctx, cores))

    starts = [e.start / YEAR for e in fd.events]
    add("bp3-fd.cells", f"{cells:g}", "m",
        "BP3-FD: fault cells (60° thrust, explicit steps in the events)")
    add("bp3-fd.events", f"{len(fd.events)} in {fd.t_last / YEAR:.0f} yr",
        "", "BP3-FD: events of the run (starts "
        + ", ".join(f"{x:.2f}" for x in starts) + " yr)")
    wall = run.resumed_wall_time(args.fd)
    if wall:
        add("bp3-fd.cost", *bench.duration(wall),
            f"BP3-FD: wall time to {fd.t_last / YEAR:.0f} yr, one rank "
            "(resumed segments summed)")
    others = [f"{element_size(f) or 0:g} m" for f in (args.coarse, args.fine)
              if f]
    add("bp3-fd.peer", "none" + ("; runs at " + " and ".join(others)
                                 if others else ""), "",
        "BP3-FD: no peer run; rsfcycle's BP3-QD and coarser and finer runs "
        "instead")
    intervals = catalog.intervals(fd.events)
    add("bp3-fd.recurrence", "no peer; intervals " + ", ".join(
        f"{x / YEAR:.2f}" for x in intervals) + " yr" if intervals else
        "one event", "", "BP3-FD: intervals of the run")
    add("bp3-fd.peak_slip_rate", "no peer; " + ", ".join(
        f"{e.peak:.2f}" for e in fd.events) + " m/s", "",
        "BP3-FD: peak slip rates")
    first = fd.events[0]
    loads = {"qd": None, "coarse": args.load, "fine": args.fine_load}
    for flag, key, what in ((args.qd, "qd", "BP3-QD's"),
                            (args.coarse, "coarse", "the coarser run's"),
                            (args.fine, "fine", "the finer run's")):
        if not flag:
            continue
        other = Run(key, flag, merge=MERGE if key == "qd" else FD_MERGE)
        if key == "fine":
            # the finer run need only have ended its first event
            other.events = [e for e in other.events
                            if e.end < other.t_last - FD_MERGE]
            if not other.events:
                sys.exit(f"{flag}: its first event has not ended an hour "
                         "before the run's end (rsfcycle --resume it)")
        if not other.events:
            continue
        o = other.events[0]
        size = element_size(flag)
        ctx, _ = run_of(flag, args.cores, loads[key])
        label = f"{what} at {size:g} m" if size else what
        add(f"bp3-fd.{key}.start", signed(percent(first.start, o.start), 2),
            "%", f"BP3-FD's first event's start against {label} "
            f"({first.start / YEAR:.2f} against {o.start / YEAR:.2f} yr)", ctx)
        if key != "qd":
            ended = [e for e in other.events if e.end < other.t_last - FD_MERGE]
            add(f"bp3-fd.{key}.events", f"{len(ended)} in "
                f"{other.t_last / YEAR:.0f} yr", "", f"BP3-FD at {size:g} m: "
                "events of the run (starts " + ", ".join(
                    f"{e.start / YEAR:.2f}" for e in ended) + " yr; peaks " +
                ", ".join(f"{e.peak:.2f}" for e in ended) + " m/s)", ctx)
            wall = run.resumed_wall_time(flag)
            if wall:
                add(f"bp3-fd.{key}.cost", *bench.duration(wall),
                    f"BP3-FD at {size:g} m: wall time to "
                    f"{other.t_last / YEAR:.0f} yr, one rank (resumed "
                    "segments summed)", ctx)
        # BP3-QD's first events may stay below the surface: its peak and
        # surface slip are those of its first rupture to the surface
        full = [e for e in other.events if e.jump and e.jump > SURFACE_SLIP]
        if not full:
            continue
        if full[0] is not o:
            o = full[0]
            label += f" (its first rupture to the surface, {o.start / YEAR:.2f} yr)"
        add(f"bp3-fd.{key}.peak", signed(percent(first.peak, o.peak), 1),
            "%", f"BP3-FD's first peak slip rate against {label} "
            f"({first.peak:.2f} against {o.peak:.2f} m/s)", ctx)
        if first.jump is not None and o.jump:
            add(f"bp3-fd.{key}.jump", signed(percent(first.jump, o.jump), 2),
                "%", f"BP3-FD's first event's slip at the surface against "
                f"{label} ({first.jump:.3f} against {o.jump:.3f} m)", ctx)
        if key != "qd" and fd.deep is not None and other.deep is not None:
            # below the surface, where the fault meets no free edge
            ours, theirs = (deep_figures(r.deep, e)
                            for r, e in ((fd, first), (other, o)))
            front = (f"in the rupture front (the {FRONT:g} s after its slip "
                     f"rate exceeds {100 * FRONT_ONSET:g} cm/s) ")
            for k, name, digits, what, unit, fmt in (
                    (0, "peak_10km", 1, "peak slip rate", "m/s", ".2f"),
                    (2, "front_10km", 1, "peak slip rate", "m/s", ".2f"),
                    (3, "front_slip_10km", 2, "slip", "m", ".3f"),
                    (1, "slip_10km", 2, "slip", "m", ".3f")):
                where = front if name.startswith("front") else ""
                add(f"bp3-fd.{key}.{name}",
                    signed(percent(ours[k], theirs[k]), digits), "%",
                    f"BP3-FD's first event's {what} 10 km down dip {where}"
                    f"against {label} ({ours[k]:{fmt}} against "
                    f"{theirs[k]:{fmt}} {unit})", ctx)
    back = explicit_until(fd.folder, first)
    add("bp3-fd.explicit_until", f"{back:.0f}", "s", "BP3-FD: the first "
        "event's explicit steps end this long after its start (then the "
        "implicit step)")
    if args.no_sponge:
        rows += sponge_rows(fd, first, args.no_sponge, args.cores)
    return rows


def explicit_until(folder, event):
    """How long after the event's start its last explicit step ends [s]
    (the explicit step is the run's shortest: trials take 4 or more)."""
    ts = run.time_series(folder)
    t, dt = ts["time_s"].to_numpy(), ts["step_size_s"].to_numpy()
    # (the explicit steps go on below the threshold, after the event's end)
    inside = (t > event.start) & (t <= event.end + FD_MERGE)
    # the explicit step: the most frequent step of the event
    sizes, counts = np.unique(dt[inside], return_counts=True)
    tau_e = sizes[np.argmax(counts)]
    last = t[inside & np.isclose(dt, tau_e, rtol=1e-9)].max()
    return last - event.start


def sponge_rows(fd, first, folder, cores):
    """The bp3-fd.sponge.* rows: the first event against a run without
    the sponge (which need not have ended it): start, peak, and the slip
    at the surface SPONGE_WINDOW after the start."""
    other = Run("no-sponge", folder, merge=FD_MERGE)
    o = other.events[0]
    ctx, _ = run_of(folder, cores)
    if min(r.top[-1, 0] - e.start
           for r, e in ((fd, first), (other, o))) < SPONGE_WINDOW:
        sys.exit(f"{folder}: ends before its first event's start + "
                 f"{SPONGE_WINDOW:g} s")
    slips = [at(r.top, e.start + SPONGE_WINDOW, 1) - at(r.top, e.start - 1, 1)
             for r, e in ((fd, first), (other, o))]
    # the surface station 8 km off the trace, in the sponge: its
    # horizontal displacement then
    shifts = [at(r.surface["+08"], e.start + SPONGE_WINDOW, 1) -
              at(r.surface["+08"], e.start - 1, 1)
              for r, e in ((fd, first), (other, o))]
    # without the sponge: how long its explicit steps went on
    back = explicit_until(other.folder, o)
    still = back > other.t_last - o.start - 1
    return [
        ("bp3-fd.sponge.start", signed(percent(first.start, o.start), 4), "%",
         "BP3-FD with the sponge against without, 50 m: the first event's "
         f"start ({first.start / YEAR:.3f} against {o.start / YEAR:.3f} yr)",
         ctx, cores),
        ("bp3-fd.sponge.peak", signed(percent(first.peak, o.peak), 2), "%",
         "BP3-FD with the sponge against without: the first peak slip rate "
         f"({first.peak:.2f} against {o.peak:.2f} m/s)", ctx, cores),
        ("bp3-fd.sponge.jump", signed(percent(*slips), 2), "%",
         "BP3-FD with the sponge against without: slip at the surface "
         f"{SPONGE_WINDOW:g} s after the start ({slips[0]:.4f} against "
         f"{slips[1]:.4f} m)", ctx, cores),
        ("bp3-fd.sponge.station", signed(percent(*shifts), 2), "%",
         "BP3-FD with the sponge against without: the surface station at "
         f"+8 km (in the sponge), its horizontal displacement "
         f"{SPONGE_WINDOW:g} s after the start ({shifts[0]:.4f} against "
         f"{shifts[1]:.4f} m)", ctx, cores),
        ("bp3-fd.sponge.explicit_until", f"{back:.0f}", "s",
         "BP3-FD without the sponge: its explicit steps after the first "
         "event's start " + ("went on until it was stopped" if still else
                             "ended"), ctx, cores),
    ]


def fd_command(args):
    """The `fd` command."""
    return write_rows(fd_rows(args), args.dry_run)


# -------------------------------------------------------------------- runs

def variant_entries(dip, sense, cells, far_field, years, problem):
    """The entries that make prm/seas-bp3-{problem}.prm the variant."""
    total = math.log2(COARSE / cells)
    if abs(total - round(total)) > 1e-9 or round(total) < FAR_FIELD[far_field]:
        sys.exit(f"--cells {cells:g}: 800 m halved a whole number of times, "
                 f"at least {FAR_FIELD[far_field]} ({far_field})")
    angle = math.radians(dip)
    sign = 1 if sense == "thrust" else -1

    def component(x):
        return "0" if abs(x) < 1e-20 else f"{x:.7g}"

    entries = {
        "End time": f"{years * YEAR:.6g}",
        "Mesh file/File": os.path.join(ROOT, "prm", "meshes",
                                       f"seas-bp3-{dip}.msh"),
        "Mesh file/Load velocity":
            f"{component(-sign * 5e-10 * math.cos(angle))}, "
            f"{component(sign * 5e-10 * math.sin(angle))}",
        "Mesh/Global refinements": FAR_FIELD[far_field],
        "Mesh/Local refinements": round(total) - FAR_FIELD[far_field],
        "Output/SEAS/Description": f"{sense}, dip {dip}",
    }
    if dip != 60:
        base = run.parameters(os.path.join(ROOT, "prm", "seas-bp3-qd.prm"))
        for name in ("a", "b - a", "Initial state"):
            key = f"Mesh file/Friction/{name}"
            entries[key] = base[key].replace(SIN[60], SIN[dip])
        if problem == "fd":
            # the sponge's distance from the fault (its angle)
            key = "Mesh file/Sponge damping"
            fd = run.parameters(os.path.join(ROOT, "prm", "seas-bp3-fd.prm"))
            entries[key] = fd[key].replace("(60 * _pi", f"({dip} * _pi")
    return entries


def runs_command(args):
    """The `runs` command."""
    binary = os.path.abspath(args.binary)
    if not args.prm_only and not os.path.isfile(binary):
        print(f"{args.binary}: not built (cmake --build build), or give "
              "--binary", file=sys.stderr)
        return 2
    base = os.path.join(ROOT, "prm", f"seas-bp3-{args.problem}.prm")
    for dip in args.dip:
        for sense in args.sense:
            for cells in args.cells or [25.0 if args.problem == "qd" else 50.0]:
                name = f"bp3-{args.problem}-{dip}-{sense}-{cells:g}m"
                if args.far_field != "g1":
                    name += "-" + args.far_field
                if args.tag:
                    name += "-" + args.tag
                folder = os.path.join(args.work, name)
                entries = variant_entries(dip, sense, cells, args.far_field,
                                          args.years, args.problem)
                for item in args.set or []:
                    key, sep, value = item.partition("=")
                    if not sep:
                        print(f"--set {item}: not Subsection/Entry=VALUE",
                              file=sys.stderr)
                        return 2
                    entries[key.strip()] = value.strip()
                if args.prm_only:
                    print(prm.variant(os.path.join(args.work, name + ".prm"),
                                      base, folder, entries))
                    continue
                print(folder + ".prm")
                bench.run_variant(binary, base, folder, entries, args.ranks)
    return 0


# ------------------------------------------------------------------- schur

SCHUR_END = 2e5  # s: BP3-FD's set-up and first steps, 9 to 11 step sizes


def timed(command, log):
    """Run `command` (output to `log`); (wall time [s], peak resident
    memory [GB]) of that process alone."""
    start = datetime.datetime.now()
    with open(log, "w") as out:
        child = subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(child.pid, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"{' '.join(command)} failed (see {log})")
    return ((datetime.datetime.now() - start).total_seconds(),
            usage.ru_maxrss / 1024 ** 2)


def schur_command(args):
    """The `schur` command: BP3-FD's first SCHUR_END seconds, 60° thrust,
    with --binary and --baseline in turn at each --cells; the rows
    bp3-fd.schur.CELLSm (wall time and peak memory against the baseline's;
    the end's maximum slip rate of the two must agree)."""
    binaries = {"binary": os.path.abspath(args.binary),
                "baseline": os.path.abspath(args.baseline)}
    version = subprocess.run([binaries["baseline"], "--version"],
                             capture_output=True, text=True).stdout
    baseline = version.split("commit ")[-1].split(",")[0][:7]
    base = os.path.join(ROOT, "prm", "seas-bp3-fd.prm")
    context = results.run_context(ROOT)
    if args.load:
        context["load"] = args.load
    rows = []
    for cells in args.cells:
        measured = {}
        for name, binary in binaries.items():
            folder = os.path.join(args.work, f"schur-{cells:g}m-{name}")
            entries = variant_entries(60, "thrust", cells, "g1", 0, "fd")
            entries["End time"] = f"{SCHUR_END:g}"
            path = prm.variant(folder + ".prm", base, folder, entries)
            wall, memory = timed([binary, "--force", path], folder + ".log")
            v = run.time_series(folder)["max_slip_rate_m_per_s"].to_numpy()[-1]
            measured[name] = (wall, memory, v)
            print(f"{cells:g} m, {name}: {wall:.1f} s, {memory:.2f} GB")
        (w1, m1, v1), (w0, m0, v0) = measured["binary"], measured["baseline"]
        if abs(v1 - v0) > 1e-6 * abs(v0):
            sys.exit(f"{cells:g} m: the maximum slip rates at the end differ "
                     f"({v1:.9g} against {v0:.9g} m/s)")
        rows.append((f"bp3-fd.schur.{cells:g}m", f"{w1 / w0:.3f}", "x",
                     f"BP3-FD at {cells:g} m, its set-up and steps to "
                     f"{SCHUR_END:g} s (a new step matrix at each new step "
                     "size): wall time of the direct correction with the "
                     "contact dofs' Schur complement from a factorisation "
                     "with them last and a Cholesky factor of S_aa + H_aa, "
                     f"against {baseline}'s (one solve per contact dof, LU): "
                     f"{w1:.1f} against {w0:.1f} s; peak memory {m1:.2f} "
                     f"against {m0:.2f} GB", context, 1))
    return write_rows(rows, args.dry_run)


# ------------------------------------------------------------------ tandem

def tandem_command(args):
    """The `tandem` command."""
    prefix = args.prefix or os.environ.get("TANDEM_PREFIX")
    if not prefix:
        print("set TANDEM_PREFIX (or --prefix) to the folder where "
              "tandem/build.sh builds tandem", file=sys.stderr)
        return 2
    env = dict(os.environ, TANDEM_PREFIX=os.path.abspath(prefix),
               LF=f"{args.lf:g}",
               DIP=str(args.dip), SENSE=args.sense, RTOL=f"{args.rtol:g}",
               TMAX=f"{args.years:g}", RESUME="1" if args.resume else "0")
    return subprocess.run(["bash", os.path.join(HERE, "tandem", "run.sh"),
                           args.out], env=env).returncode


# -------------------------------------------------------------------- main

def equal_command(args):
    """The cost at equal accuracy against HBI: the shipped 60° thrust run
    (prm/seas-bp3-qd.prm, 1500 years at 25 m) and HBI's, each at its
    cheapest run whose catalogue is unchanged (rsfcycle.equal)."""
    return hbi.equal_command(args, HERE, "bp3", "prm/seas-bp3-qd.prm", "1e-5",
                             lambda folder: Run("", folder).events)


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="PYTHONPATH=python /usr/bin/python3 benchmarks/seas-bp3/run.py",
        description=__doc__.split("\n\n")[0],
        epilog=__doc__.split("\n\n", 1)[1],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)

    p = sub.add_parser("runs", help="rsfcycle's BP3 variants into --work "
                       "(1500 years at 25 m: 13.6 - 34 min each on one shared core)")
    p.add_argument("--dip", type=int, nargs="+", choices=(30, 60, 90),
                   default=[60])
    p.add_argument("--sense", nargs="+", choices=("thrust", "normal"),
                   default=["thrust"])
    p.add_argument("--cells", type=float, nargs="+",
                   help="m on the fault: 800 halved N times (default 25; "
                   "BP3-FD 50)")
    p.add_argument("--far-field", choices=sorted(FAR_FIELD), default="g1",
                   help="cells away from the fault halved 0, 1 or 2 times "
                   "(Mesh/Global refinements; g1 is shipped)")
    p.add_argument("--years", type=float, default=1500)
    p.add_argument("--problem", choices=("qd", "fd"), default="qd",
                   help="prm/seas-bp3-qd.prm or prm/seas-bp3-fd.prm")
    p.add_argument("--work", default=os.path.join(HERE, "runs"),
                   help="default benchmarks/seas-bp3/runs (git-ignored)")
    p.add_argument("--binary", default=os.path.join(ROOT, "build",
                                                     "rsfcycle"))
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--set", action="append", metavar="ENTRY=VALUE",
                   help="any other entry, e.g. 'Solver/Bulk=volume' "
                   "(repeatable; after the variant's own)")
    p.add_argument("--tag", help="appended to the run folder's name")
    p.add_argument("--prm-only", action="store_true",
                   help="write the parameter files, run nothing")
    p.set_defaults(handler=runs_command)

    for name, handler, text in (
            ("tables", tables, "run folders' events side by side and "
             "paired with the first's (Markdown, to stdout)"),
            ("figures", figures, "max slip rate and surface slip against "
             "time, figures/sequence.png or --output")):
        p = sub.add_parser(name, help=text)
        p.add_argument("runs", nargs="+", metavar="NAME=FOLDER",
                       help="the first is the reference of the pairs")
        p.add_argument("--until", type=float, default=math.inf,
                       help="only events that start before (years)")
        if name == "tables":
            p.add_argument("--events", type=int,
                           help="pair only the first N events")
        else:
            p.add_argument("--output", help="PNG file (default "
                           "benchmarks/seas-bp3/figures/sequence.png)")
            p.add_argument("--title")
        p.set_defaults(handler=handler)

    p = sub.add_parser("results", help="rows of results.csv from an "
                       "rsfcycle run and the peers'")
    p.add_argument("--dip", type=int, choices=(30, 60, 90), required=True)
    p.add_argument("--sense", choices=("thrust", "normal"), required=True)
    p.add_argument("--rsf", required=True, help="rsfcycle's run folder")
    p.add_argument("--hbi", help="HBI's run folder (rsfcycle.peers.hbi run)")
    p.add_argument("--tandem", help="tandem's run folder (tandem/run.sh): "
                   "the tandem.* rows")
    p.add_argument("--events", type=int, help="compare the first N events "
                   "(60° thrust: 4, where the orders part)")
    p.add_argument("--recurrence-from", type=int, default=1,
                   help="mean recurrence from event K on (default 1)")
    p.add_argument("--seas-table", action="store_true",
                   help="also the bp3-qd.* rows of README.md's SEAS table "
                   "(the shipped 60° thrust run)")
    p.add_argument("--peer-cells", type=float,
                   help="HBI's cell size [m] (default rsfcycle's)")
    p.add_argument("--cores", type=int, default=1)
    p.add_argument("--load", help="the machine's load during the run "
                   "(default: what `runs` saw before it, else empty)")
    p.add_argument("--dry-run", action="store_true",
                   help="print the rows, write nothing")
    p.set_defaults(handler=results_command)

    p = sub.add_parser("fd", help="the bp3-fd.* rows of results.csv: a "
                       "BP3-FD run's events against BP3-QD's and coarser "
                       "and finer BP3-FD runs' first event")
    p.add_argument("--fd", required=True, help="the BP3-FD run folder "
                   "(runs --problem fd)")
    p.add_argument("--qd", help="a BP3-QD run folder with the same cells")
    p.add_argument("--coarse", help="a BP3-FD run folder with coarser cells")
    p.add_argument("--fine", help="a BP3-FD run folder with finer cells, "
                   "run at least to its first event's end (the bp3-fd.fine.* "
                   "rows)")
    p.add_argument("--fine-load", help="the machine's load during the "
                   "finer run")
    p.add_argument("--no-sponge", help="a BP3-FD run folder with the same "
                   "cells and no sponge (runs --set 'Mesh file/Sponge "
                   "damping='), run at least 100 s into its first event")
    p.add_argument("--cores", type=int, default=1)
    p.add_argument("--load", help="the machine's load during the run")
    p.add_argument("--dry-run", action="store_true",
                   help="print the rows, write nothing")
    p.set_defaults(handler=fd_command)

    p = sub.add_parser("schur", help="the direct correction's set-up "
                       "against a baseline binary's: BP3-FD's first "
                       f"{SCHUR_END:g} s at each --cells, one after the other")
    p.add_argument("--baseline", required=True, help="the binary to compare "
                   "with (one that solves once per contact dof)")
    p.add_argument("--binary", default=os.path.join(ROOT, "build",
                                                    "rsfcycle"))
    p.add_argument("--cells", type=float, nargs="+", default=[100.0, 50.0])
    p.add_argument("--work", default=os.path.join(HERE, "runs"),
                   help="default benchmarks/seas-bp3/runs (git-ignored)")
    p.add_argument("--load", help="the machine's load during the runs "
                   "(default: measured before them)")
    p.add_argument("--dry-run", action="store_true",
                   help="print the rows, write nothing")
    p.set_defaults(handler=schur_command)

    p = sub.add_parser("equal", help="the cost at equal accuracy against "
                       "HBI (each code's cheapest run with unchanged results)")
    p.add_argument("--work", default=os.path.join(HERE, "runs"),
                   help="default benchmarks/seas-bp3/runs (git-ignored)")
    hbi.equal_arguments(p)
    p.set_defaults(handler=equal_command)

    p = sub.add_parser("tandem", help="run tandem (tandem/run.sh): "
                       "TANDEM_PREFIX or --prefix")
    p.add_argument("out", help="tandem's run folder")
    p.add_argument("--prefix", help="where tandem/build.sh builds tandem "
                   "(default $TANDEM_PREFIX)")
    p.add_argument("--lf", type=float, default=0.1,
                   help="fault element size [km], degree 4 (default 0.1)")
    p.add_argument("--dip", type=int, choices=(30, 60, 90), default=60)
    p.add_argument("--sense", choices=("thrust", "normal"), default="thrust")
    p.add_argument("--rtol", type=float, default=1e-7,
                   help="RK45's absolute tolerance (tandem's rk45.cfg)")
    p.add_argument("--years", type=float, default=1500)
    p.add_argument("--resume", action="store_true",
                   help="continue from the run's last checkpoint")
    p.set_defaults(handler=tandem_command)

    args = parser.parse_args(argv)
    return args.handler(args)


if __name__ == "__main__":
    sys.exit(main())
