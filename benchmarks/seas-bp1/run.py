#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""SEAS BP1-QD, BP1-FD and BP2-QD: rsfcycle against QDYN and SCycle
(README.md in this folder). From the repository's root:

  PYTHONPATH=python /usr/bin/python3 benchmarks/seas-bp1/run.py COMMAND ...

  runs [NAME ...]   rsfcycle's runs (build/rsfcycle) into WORK/NAME;
                    --list names them with their cost
  peers [NAME ...]  QDYN (QDYN_SRC) and SCycle (SCYCLE_SRC) through
                    qdyn/run.sh and scycle/run.sh into WORK/qdyn,
                    WORK/scycle-*; --list names them
  results           benchmarks/seas-bp1/results.csv from the run folders
                    in WORK (rsfcycle.results.record), and the event-by-
                    event comparisons printed
  cost              rsfcycle against QDYN at equal accuracy: each at the
                    loosest tolerance that leaves its own 1000-year
                    catalogue unchanged
  figures           every figure of the README into figures/ from WORK
  cycles            log10 V at fault stations cycle by cycle, rsfcycle's
                    BP1-QD runs against QDYN's

WORK is each command's --work (default benchmarks/seas-bp1/runs, not
tracked). `results` and `figures` use the run folders they find and name
the ones they miss. An event is where the maximum slip rate exceeds
1 mm/s (rsfcycle.catalog), the same for every code; BP1-FD joins rises
less than an hour apart.
"""

import argparse
import datetime
import json
import os
import re
import resource
import subprocess
import sys
import time

try:
    import numpy as np
    from rsfcycle import bench, catalog, prm, results, run, seas
    from rsfcycle.bench import duration
    from rsfcycle.equal import cheapest_unchanged, unchanged
    from rsfcycle.equal import table as equal_table
    from rsfcycle.peers import PeerNotFound, qdyn, scycle, source, time_v
except ImportError as error:
    print(f"run.py: {error}: run from the repository's root with "
          "PYTHONPATH=python and /usr/bin/python3 (numpy, pandas, "
          "matplotlib)", file=sys.stderr)
    sys.exit(2)

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
YEAR = catalog.YEAR
THRESHOLD = 1e-3  # [m/s]
FD_MERGE = 3600.0  # [s]: BP1-FD's Output/Event merge time
NO_VTU = {"Output/Writers": "time series, base profile, events, seas"}
FD3 = dict(NO_VTU, **{"Stop after events": 3})
FD1 = dict(NO_VTU, **{"Stop after events": 1})
# explicit steps inside the events, implicit ones between them (shipped)
IE = {"Time stepping/Integrator": "implicit-explicit",
      "Solver/Mass matrix": "lumped"}
# the implicit step throughout with the consistent mass and the multigrid
# correction: BP1-FD's set-up of the comparison with SCycle and of the
# grid studies (bp1-fd.* rows)
IMPLICIT = {"Time stepping/Integrator": "implicit",
            "Solver/Mass matrix": "consistent",
            "Solver/Linear correction": "multigrid",
            "Solver/Direct factor reuse": "false",
            "Solver/Linear correction cycles": 20}
# a sponge (Mesh file/Sponge damping, doc/model.md 8.3b): 0 within 40 km
# of the frictional fault, growing as the square of the distance beyond to
# 0.5/s at 200 km
SPONGE = ("0.5 * min(1, max(0, (sqrt(x^2 + max(0, -y - 40e3)^2) - 40e3)"
          " / 160e3))^2")
FD3I = dict(FD3, **IMPLICIT)
FD1I = dict(FD1, **IMPLICIT)


def mesh(name):
    return os.path.join(ROOT, "prm", "meshes", name)


# rsfcycle's runs: name -> (shipped .prm, entries, what it is, the key of
# its measured cost in results.csv or "")
RUNS = {
    "bp1-qd": ("seas-bp1-qd.prm", {}, "BP1-QD as shipped: 25 m, 3000 yr",
               "bp1-qd.cost"),
    "bp1-qd-50m": ("seas-bp1-qd.prm", {"Mesh/Local refinements": 5},
                   "BP1-QD at 50 m", "bp1-qd.50m.cost"),
    "bp1-qd-volume": ("seas-bp1-qd.prm", {
        "Mesh/Local refinements": 5, "Solver/Bulk": "volume",
        "Time stepping/Integrator": "implicit"},
        "BP1-QD at 50 m, the implicit step over the volume",
        "bp1-qd.volume.cost"),
    "bp1-qd-200m": ("seas-bp1-qd.prm", {"Mesh/Local refinements": 3},
                    "BP1-QD at 200 m (400 km body)", ""),
    "bp1-qd-800km": ("seas-bp1-qd.prm", {
        "Mesh/Local refinements": 3,
        "Mesh file/File": mesh("seas-bp1-800km.msh")},
        "BP1-QD at 200 m on an 800 km body", ""),
    "bp1-fd": ("seas-bp1-fd.prm", FD3,
               "BP1-FD as shipped (50 m, explicit steps in the events) to "
               "its third event", "bp1-fd.switch.cost"),
    "bp1-fd-tol3e-5": ("seas-bp1-fd.prm", dict(FD3, **{
        "Time stepping/Tolerance": "3e-5"}),
        "BP1-FD as shipped at delta 3e-5 (`cost`)", ""),
    "bp1-fd-implicit": ("seas-bp1-fd.prm", FD3I,
                        "BP1-FD with the implicit step throughout "
                        "(consistent mass, multigrid) to its third event",
                        "bp1-fd.implicit_cost"),
    "bp1-fd-25m": ("seas-bp1-fd.prm", dict(FD3I, **{
        "Mesh/Local refinements": 6}), "BP1-FD at 25 m, three events", ""),
    "bp1-fd-200m": ("seas-bp1-fd.prm", dict(FD3I, **{
        "Mesh/Local refinements": 3}), "BP1-FD at 200 m, three events", ""),
    "bp1-fd-d3": ("seas-bp1-fd.prm", dict(FD3I, **{
        "Mesh/Refinement distance": 3}), "BP1-FD, Refinement distance 3",
        ""),
    "bp1-fd-d5": ("seas-bp1-fd.prm", dict(FD3I, **{
        "Mesh/Refinement distance": 5}), "BP1-FD, Refinement distance 5",
        ""),
    "bp1-fd-d6": ("seas-bp1-fd.prm", dict(FD3I, **{
        "Mesh/Refinement distance": 6}), "BP1-FD, Refinement distance 6",
        ""),
    "bp1-fd-wp-1e-3": ("seas-bp1-fd.prm", dict(FD1I, **{
        "Time stepping/Tolerance": "1e-3"}), "BP1-FD's first event, "
        "delta 1e-3", ""),
    "bp1-fd-wp-1e-4": ("seas-bp1-fd.prm", dict(FD1I, **{
        "Time stepping/Tolerance": "1e-4"}), "the same, delta 1e-4", ""),
    "bp1-fd-wp-1e-5": ("seas-bp1-fd.prm", FD1I,
                       "the same, delta 1e-5 (shipped)", ""),
    "bp1-fd-wp-rho0": ("seas-bp1-fd.prm", dict(FD1I, **{
        "Solver/Spectral radius": 0}), "the same, rho_inf = 0", ""),
    "bp1-fd-wp-25m": ("seas-bp1-fd.prm", dict(FD1I, **{
        "Mesh/Local refinements": 6}), "the same at 25 m", ""),
    "bp1-fd-implicit-lumped": ("seas-bp1-fd.prm", dict(FD1I, **{
        "Solver/Mass matrix": "lumped"}),
        "BP1-FD's first event, the implicit step throughout with the "
        "explicit steps' lumped mass", ""),
    "bp1-fd-ie": ("seas-bp1-fd.prm", dict(FD1, **IE),
                  "BP1-FD's first event, implicit-explicit (lumped mass, "
                  "Courant number 0.5)", "bp1-fd.ie.cost"),
    "bp1-fd-ie-25m": ("seas-bp1-fd.prm", dict(FD1, **IE, **{
        "Mesh/Local refinements": 6}), "the same at 25 m", ""),
    "bp1-fd-ie-sponge": ("seas-bp1-fd.prm", dict(FD1, **IE, **{
        "Mesh file/Sponge damping": SPONGE}),
        "the same with a sponge from 40 km off the fault", ""),
    "bp1-fd-ie-d5": ("seas-bp1-fd.prm", dict(FD1, **IE, **{
        "Mesh/Refinement distance": 5}),
        "the same with the bulk refined 5 cells out (shipped: 4)", ""),
    "bp1-fd-ie-d6": ("seas-bp1-fd.prm", dict(FD1, **IE, **{
        "Mesh/Refinement distance": 6}),
        "the same with the bulk refined 6 cells out (shipped: 4)", ""),
    "bp1-fd-ie-c025": ("seas-bp1-fd.prm", dict(FD1, **IE, **{
        "Time stepping/Courant number": 0.25}),
        "the same, Courant number 0.25", ""),
    "bp2-qd": ("seas-bp2-qd.prm", {}, "BP2-QD as shipped: 12.5 m, 800 km "
               "body, 1200 yr", "bp2-qd.cost"),
    "bp2-qd-25m": ("seas-bp2-qd.prm", {
        "Mesh/Local refinements": 6, "Mesh file/File": mesh("seas-bp1.msh")},
        "BP2-QD at 25 m on BP1's 400 km body", ""),
}
# equal accuracy (`cost`): 1000 QDYN years (365 days) of BP1-QD at the
# shipped step tolerance and looser ones
EQUAL = 3.1536e10  # [s]
for _tol in ("1e-5", "3e-5", "1e-4", "3e-4"):
    RUNS["bp1-qd-1000yr-" + _tol] = (
        "seas-bp1-qd.prm", {"End time": EQUAL, **NO_VTU,
                            "Time stepping/Tolerance": _tol},
        f"BP1-QD, 25 m, 1000 yr, delta {_tol} (`cost`)", "")

# the peers' runs: name -> (script, folder in WORK, arguments, the run's
# name in the folder (QDYN), what it is, cost key)
PEERS = {
    "qdyn-bp1": ("qdyn", "qdyn", [], "A_L40_N2048",
                 "QDYN, BP1-QD, N = 2048 (19.5 m)", "bp1-qd.peer_cost"),
    "qdyn-bp2": ("qdyn", "qdyn", ["--bp2-only"], "BP2_L40_N2048",
                 "QDYN, BP2-QD, N = 2048", "bp2-qd.peer_cost"),
    "qdyn-bp1-n1024": ("qdyn", "qdyn", ["--n", "1024"], "A_L40_N1024",
                       "QDYN, BP1-QD, N = 1024 (39.1 m)", ""),
    "scycle-50m": ("scycle", "scycle-50m", [], "",
                   "SCycle, BP1-FD, 50 m, three events", "bp1-fd.peer_cost"),
    "scycle-50m-3e-5": ("scycle", "scycle-50m-3e-5",
                        ["--trigger-qd2fd", "3e-5", "--limit-qd", "3e-6"], "",
                        "the same, the wave equation from 0.03 mm/s", ""),
    "scycle-50m-tol1e-6": ("scycle", "scycle-50m-tol1e-6",
                           ["--time-step-tol", "1e-6"], "",
                           "the same, timeStepTol 1e-6 (`cost`)", ""),
    "scycle-100m": ("scycle", "scycle-100m",
                    ["--h", "0.1", "--trigger-qd2fd", "1e-4"], "",
                    "SCycle at 100 m, the wave equation from 0.1 mm/s", ""),
}
for _acc in ("1e-8", "1e-7", "1e-6", "1e-5", "1e-4", "1e-3"):
    PEERS["qdyn-bp1-1000yr-" + _acc] = (
        "qdyn", "qdyn-1000yr", ["--tmax", "1000", "--acc", _acc],
        "A_L40_N2048" + ("" if _acc == "1e-8" else "_ACC" + _acc),
        f"QDYN, BP1-QD, N = 2048, 1000 yr, ACC {_acc} (`cost`)", "")
SOURCES = {"qdyn": ("QDYN_SRC", "src/pyqdyn.py", qdyn.URL),
           "scycle": ("SCYCLE_SRC", "source/Makefile", scycle.URL)}


def measured_cost(key):
    """The cost of a run as results.csv states it, or ''."""
    if not key:
        return ""
    rows = results.read_results(os.path.join(HERE, "results.csv"))
    return rows[key].text() + f" ({rows[key].cores} core)" if key in rows \
        else ""


# ---------------------------------------------------------------- runs


def cmd_runs(args):
    """Run rsfcycle's variants of prm/seas-bp1-qd.prm, seas-bp1-fd.prm and
seas-bp2-qd.prm one after the other: WORK/NAME.prm (rsfcycle.prm.variant)
into WORK/NAME; WORK/NAME.json keeps the commit, date, machine load,
ranks, wall and CPU time. Without names (or with --list): the names, what
each run is and its cost as results.csv states it. bp1-qd, bp1-qd-50m,
bp1-fd and bp2-qd give the main tables."""
    if args.list or not args.names and not args.all:
        for name, (base, entries, text, key) in RUNS.items():
            print(f"{name:16} {text}; {measured_cost(key) or 'not measured'}")
        return 0
    names = list(RUNS) if args.all else args.names
    for name in names:
        if name not in RUNS:
            print(f"run.py: no run '{name}' (run.py runs --list)",
                  file=sys.stderr)
            return 2
    binary = bench.executable(args.build)
    os.makedirs(args.work, exist_ok=True)
    for name in names:
        base, entries, text, _ = RUNS[name]
        folder = os.path.join(args.work, name)
        path = prm.variant(os.path.join(args.work, name + ".prm"),
                           os.path.join(ROOT, "prm", base), folder, entries)
        command, env = [binary, path], None
        if args.ranks > 1:
            command = bench.mpirun(args.ranks, command)
            env = bench.mpi_environment()
        print(f"{name}: {text}: {' '.join(command)}", flush=True)
        context = dict(results.run_context(ROOT), cores=args.ranks)
        rc = timed(command, os.path.join(args.work, name + ".json"), context,
                   env)
        if rc:
            print(f"run.py: {name} failed (exit status {rc}); see "
                  f"{folder}/log.txt", file=sys.stderr)
            return 1
    return 0


def timed(command, path, context, env=None):
    """Run a command; write its context with wall and CPU time [s] (its
    processes' user + system time) to the JSON file path. Returns the
    exit status."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.time()
    rc = subprocess.run(command, env=env).returncode
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    context.update(wall_s=time.time() - start, exit_status=rc,
                   cpu_s=after.ru_utime + after.ru_stime - before.ru_utime
                   - before.ru_stime)
    with open(path, "w", encoding="utf-8") as f:
        json.dump(context, f, indent=1)
    return rc


# --------------------------------------------------------------- peers


def cmd_peers(args):
    """Run the peers through qdyn/run.sh and scycle/run.sh (each checks
out and builds its pinned commit) into WORK/qdyn and WORK/scycle-*; the
clones come from --qdyn-src and --scycle-src or QDYN_SRC and SCYCLE_SRC.
WORK/NAME.json keeps the context of each run. Without names (or with
--list): the names and their cost as results.csv states it. qdyn-bp1,
qdyn-bp2 and scycle-50m give the main tables."""
    if args.list or not args.names:
        for name, (_, _, _, _, text, key) in PEERS.items():
            print(f"{name:16} {text}; {measured_cost(key) or 'not measured'}")
        return 0
    for name in args.names:
        if name not in PEERS:
            print(f"run.py: no peer run '{name}' (run.py peers --list)",
                  file=sys.stderr)
            return 2
    env = dict(os.environ)
    # the package run.py imports, for the scripts' python3 -m rsfcycle...
    package = os.path.dirname(os.path.dirname(os.path.abspath(
        results.__file__)))
    env["PYTHONPATH"] = package + (os.pathsep + env["PYTHONPATH"]
                                   if env.get("PYTHONPATH") else "")
    for name in args.names:
        script, folder, options, _, text, _ = PEERS[name]
        variable, marker, url = SOURCES[script]
        try:
            env[variable] = source(variable, getattr(args, variable.lower()),
                                   marker, url)
        except PeerNotFound as e:
            print(f"run.py: {e}", file=sys.stderr)
            return 2
        out = os.path.join(args.work, folder)
        command = [os.path.join(HERE, script, "run.sh"), out] + options
        print(f"{name}: {text}: {' '.join(command)}", flush=True)
        context = dict(results.run_context(ROOT), cores=1)
        os.makedirs(args.work, exist_ok=True)
        if timed(command, os.path.join(args.work, name + ".json"), context,
                 env):
            print(f"run.py: {name} failed", file=sys.stderr)
            return 1
    return 0


# ------------------------------------------------- the runs' time series


class Series:
    """A run reduced for the comparison: label, t [s], max slip rate
    [m/s], surface slip [m]; `folder` holds its fltst_dpXXX and devol.dat
    (None for QDYN), `events` the catalogue if the peer has its own."""

    def __init__(self, label, t, v, slip, folder=None, events=None):
        self.label, self.t, self.v, self.slip = label, t, v, slip
        self.folder, self.own_events = folder, events

    def events(self, merge=0.0):
        """The catalogue: the peer's own (every step) or detected."""
        if self.own_events is not None:
            return self.own_events
        return catalog.detect(self.t, self.v, THRESHOLD, merge,
                              series=self.slip)

    def station(self, code):
        """(t [s], log10 slip rate, shear stress [MPa]) of fltst_dpCODE."""
        _, d = seas.table(os.path.join(self.folder, "fltst_dp" + code))
        return d[:, 0], d[:, 2], d[:, 3]


def rsfcycle_series(work, name, label):
    """An rsfcycle run folder: the maximum slip rate of time-series.csv,
    the surface slip of fltst_dp000; None if the run is missing."""
    folder = os.path.join(work, name)
    if not os.path.exists(os.path.join(folder, "fltst_dp000")):
        return None
    ts = run.time_series(folder)
    _, station = seas.table(os.path.join(folder, "fltst_dp000"))
    t = ts["time_s"].values
    return Series(label, t, ts["max_slip_rate_m_per_s"].values,
                  np.interp(t, station[:, 0], station[:, 1]), folder)


def peer_folder(work, name):
    """The folder of a peer run (QDYN: its run folder)."""
    _, folder, _, qdyn_name, _, _ = PEERS[name]
    return os.path.join(work, folder, qdyn_name)


def peer_series(work, name, label):
    """A peer's series (QDYN: with its own event table), or None."""
    script, folder, _, qdyn_name, _, _ = PEERS[name]
    if script == "qdyn":
        out = os.path.join(work, folder)
        path = os.path.join(out, qdyn_name + "_series.csv")
        table = os.path.join(out, f"stats_{qdyn_name}_events.csv")
        if not os.path.exists(path) or not os.path.exists(table):
            return None
        return Series(label, *qdyn.read_series(path),
                      events=qdyn.read_events(table))
    path = os.path.join(work, folder, "series.csv")
    if not os.path.exists(path):
        return None
    return Series(label, *scycle.read_series(path),
                  folder=os.path.join(work, folder, "seas"))


def load(work, items, why):
    """The Series of [(name, label)] that exist (rsfcycle's runs and the
    peers' by name); prints the missing ones."""
    found = []
    for name, label in items:
        s = (peer_series if name in PEERS else rsfcycle_series)(
            work, name, label)
        if s is None:
            print(f"{why}: no run folder {name} in {work}")
        else:
            found.append(s)
    return found


# ------------------------------------------------------------- results


def relative(a, b):
    return (a - b) / b


def signed(x, digits=2):
    """100 x with its sign, a Unicode minus ('−0.21')."""
    return f"{100 * x:+.{digits}f}".replace("-", "\u2212")


def span(values, digits=2):
    """'−0.21 … +0.02' of relative differences."""
    low, high = signed(min(values), digits), signed(max(values), digits)
    return f"{low} \u2026 {high}"


def context_of(work, name, folder=None):
    """commit, date, load and cores of a run: its JSON file from `runs` or
    `peers` (else the date of its folder); an rsfcycle run's commit from
    its log.txt."""
    path = os.path.join(work, name + ".json")
    context = {"commit": "unknown", "date": "", "load": "", "cores": 1}
    if os.path.exists(path):
        with open(path, encoding="utf-8") as f:
            context.update(json.load(f))
    folder = folder or (peer_folder(work, name) if name in PEERS else
                        os.path.join(work, name))
    if name in RUNS and os.path.exists(os.path.join(folder, "log.txt")):
        words = run.version(folder).replace(",", " ").split()
        if "commit" in words:
            context["commit"] = words[words.index("commit") + 1][:7]
    if not context["date"] and os.path.exists(folder):
        context["date"] = time.strftime("%Y-%m-%d", time.localtime(
            os.path.getmtime(folder)))
    return context


def element_size(folder):
    """The element size [m] of a folder's SEAS headers."""
    keys = seas.SeasFile(os.path.join(folder, "fltst_dp000")).keys
    return float(keys["element_size"].split()[0])


def summary(events, skip):
    """First start, mean interval after `skip` intervals, medians of peak
    and jump after `skip` events."""
    gaps = np.diff([e.start for e in events])[skip:]
    late = events[skip:] or events
    return {"first": events[0].start,
            "interval": np.mean(gaps) if len(gaps) else np.nan,
            "peak": np.median([e.peak for e in late]),
            "jump": np.median([e.jump for e in late])}


class Recorder:
    """results.record() with a run's context."""

    def __init__(self, work):
        self.work = work

    def __call__(self, key, value, unit, description, name, folder=None):
        c = context_of(self.work, name, folder)
        results.record(HERE, key, value, unit, description, c["cores"],
                       {k: str(c[k]) for k in ("commit", "date", "load")})
        print(f"{key}: {value} {unit}  ({description})")


def compare_qd(record, ours, peer, prefix, skip, name, years, lead=""):
    """The rows of a quasi-dynamic run against QDYN (descriptions after
    `lead`); prints the table. Returns the run's wall time [s]."""
    a, b = ours.events(), peer.events()
    print(catalog.markdown(catalog.compare(a, b), ours.label, peer.label))
    sa, sb = summary(a, skip), summary(b, skip)
    n = len(a)
    rows = {
        "first_event": (relative(sa["first"], sb["first"]),
                        f"first event's start against QDYN ("
                        f"{sa['first'] / YEAR:.3f} against "
                        f"{sb['first'] / YEAR:.3f} yr)"),
        "recurrence": (relative(sa["interval"], sb["interval"]),
                       f"recurrence against QDYN (events {skip + 1} – {n}: "
                       f"{sa['interval'] / YEAR:.2f} against "
                       f"{sb['interval'] / YEAR:.2f} yr)"),
        "peak_slip_rate": (relative(sa["peak"], sb["peak"]),
                           f"median peak slip rate against QDYN's "
                           f"{sb['peak']:.4f} m/s"),
        "surface_slip": (relative(sa["jump"], sb["jump"]),
                         f"median coseismic surface slip against QDYN "
                         f"({sa['jump']:.4f} against {sb['jump']:.4f} m)"),
    }
    for key, (x, text) in rows.items():
        record(f"{prefix}.{key}", f"{100 * x:+.2f}", "%", lead + text, name,
               ours.folder)
    wall = run.wall_time(ours.folder)
    if wall:
        record(f"{prefix}.cost", *duration(wall),
               f"{lead}wall time, {years} years, operator included", name,
               ours.folder)
    return wall


def cmd_results(args):
    """Write the rows of benchmarks/seas-bp1/results.csv that the run
folders in WORK give (rsfcycle.results.record with each run's commit,
date, cores and load) and print the event-by-event comparisons; the rows
of runs not found stay as they are. Then refresh the README with
PYTHONPATH=python python3 -m rsfcycle.results write benchmarks/seas-bp1"""
    work = args.work
    record = Recorder(work)
    # BP1-QD against QDYN
    runs_ = load(work, [("qdyn-bp1", "QDYN"), ("bp1-qd", "25 m")], "bp1-qd")
    if len(runs_) == 2:
        peer, ours = runs_
        a, b = ours.events(), peer.events()
        size = element_size(ours.folder)
        record("bp1-qd.cells", f"{size:g}", "m", "fault cells "
               "(Green's-function method with the H-matrix)", "bp1-qd",
               ours.folder)
        record("bp1-qd.events", f"{len(a)} in {ours.t[-1] / YEAR:.0f} yr", "",
               f"events above 1 mm/s (QDYN: {len(b)})", "bp1-qd", ours.folder)
        n, length = qdyn.read_mesh(peer_folder(work, "qdyn-bp1"))
        record("bp1-qd.peer", f"QDYN at {length / n:.1f} m", "",
               f"peer: QDYN {qdyn.COMMIT[:7]}, N = {n}", "bp1-qd",
               ours.folder)
        wall = compare_qd(record, ours, peer, "bp1-qd", 4, "bp1-qd", 3000)
        timing = os.path.join(peer_folder(work, "qdyn-bp1"), "time.txt")
        if os.path.exists(timing) and wall:
            peer_wall = time_v(timing)["wall_s"]
            record("bp1-qd.peer_cost", *duration(peer_wall),
                   f"QDYN's wall time, 3000 years at {length / n:.1f} m",
                   "qdyn-bp1")
            record("bp1-qd.cost_ratio", f"{wall / peer_wall:.2f}", "x",
                   "rsfcycle's wall time over QDYN's, 3000 years at the "
                   "tolerances above (delta 1e-5, ACC 1e-8)", "bp1-qd", ours.folder)
    found = load(work, [("qdyn-bp1", "QDYN"), ("bp1-qd-50m", "50 m")],
                 "bp1-qd.50m")
    if len(found) == 2:
        compare_qd(record, found[1], found[0], "bp1-qd.50m", 4, "bp1-qd-50m",
                   3000, "50 m: ")
    found = load(work, [("bp1-qd-50m", "Green's function 50 m"),
                        ("bp1-qd-volume", "volume 50 m")], "bp1-qd.volume")
    if len(found) == 2:
        green, volume = found
        a, b = green.events(), volume.events()
        rows = catalog.compare(a, b)
        print(catalog.markdown(rows, green.label, volume.label))
        record("bp1-qd.volume.first_event", f"{100 * rows[0]['start']:+.2f}",
               "%", "Green's-function against volume method at 50 m: first "
               "event", "bp1-qd-50m", green.folder)
        record("bp1-qd.volume.intervals", span(
            [r["interval"] for r in rows if r["interval"] is not None]), "%",
            "Green's-function against volume method at 50 m: every "
            "interval", "bp1-qd-50m", green.folder)
        wall = run.wall_time(volume.folder)
        if wall:
            record("bp1-qd.volume.cost", *duration(wall), "volume method "
                   "(Bulk = volume) at 50 m: wall time, 3000 years",
                   "bp1-qd-volume", volume.folder)
    found = load(work, [("qdyn-bp1", "N = 2048"),
                        ("qdyn-bp1-n1024", "N = 1024")], "bp1-qd.qdyn_cells")
    if len(found) == 2:
        fine, coarse = (summary(s.events(), 4) for s in found)
        worst = max(abs(relative(fine[k], coarse[k]))
                    for k in ("first", "interval"))
        record("bp1-qd.qdyn_cells", f"{100 * worst:.2f}", "%",
               "QDYN 19.5 m against 39.1 m: first event and recurrence",
               "qdyn-bp1-n1024")
    found = load(work, [("bp1-qd-200m", "400 km"), ("bp1-qd-800km", "800 km")],
                 "bp1-qd.domain")
    if len(found) == 2:
        near, far = (summary(s.events(), 4) for s in found)
        for key, what in (("recurrence", "interval"), ("first_event",
                                                       "first")):
            record(f"bp1-qd.domain.{key}",
                   f"{100 * relative(far[what], near[what]):+.3g}", "%",
                   f"body 400 → 800 km (200 m cells): "
                   f"{key.replace('_', ' ')}", "bp1-qd-800km",
                   found[1].folder)
    results_fd(work, record)
    results_fd_ie(work, record)
    results_fd_switch(work, record)
    results_bp2(work, record)
    return 0


def results_fd_ie(work, record):
    """BP1-FD's first event with explicit steps inside it: its figures
    (SCycle's are in the rows bp1-fd.*), its cost against the implicit
    step's (bp1-fd-wp-1e-5, the same first event), and against the implicit
    step throughout with the same lumped mass (bp1-fd-implicit-lumped),
    which tells the explicit steps' part of the gap to SCycle from the
    lumped mass's."""
    for name, path in (
            ("bp1-fd-ie", "implicit-explicit, Courant number 0.5"),
            ("bp1-fd-ie-c025", "implicit-explicit, Courant number 0.25"),
            ("bp1-fd-ie-25m", "implicit-explicit, 25 m, Courant number 0.5"),
            ("bp1-fd-ie-d5", "implicit-explicit, Refinement distance 5"),
            ("bp1-fd-ie-d6", "implicit-explicit, Refinement distance 6"),
            ("bp1-fd-implicit-lumped",
             "implicit step throughout, lumped mass")):
        found = load(work, [(name, path)], name)
        if not found:
            continue
        key = name.replace("bp1-fd-", "bp1-fd.")
        # (bp1-fd-ie is the shipped file's first event, whose figures are
        # the rows bp1-fd.*: only its cost here)
        peer = load(work, [("scycle-50m", "SCycle 50 m")], key + ".scycle")
        if peer and name != "bp1-fd-ie":
            record_gaps(record, lambda f: f"{key}.scycle_{f}",
                        f"{path}: first event's {{text}} "
                        "against SCycle's at 50 m", first_event(found[0]),
                        first_event(peer[0]), name, found[0].folder,
                        ("peak", "jump"), 1)
        mine = context_of(work, name, found[0].folder)
        if "cpu_s" in mine:
            cpu = int(round(mine["cpu_s"]))
            record(f"{key}.cost", f"{cpu // 60} min {cpu % 60:02d}", "s",
                   f"{path}: CPU time of one core to "
                   "the first event's end", name, found[0].folder)
            implicit = context_of(work, "bp1-fd-wp-1e-5")
            if "cpu_s" in implicit:
                record(f"{key}.cost_ratio",
                       f"{mine['cpu_s'] / implicit['cpu_s']:.2f}", "x",
                       f"{path}: CPU time over the "
                       "implicit step's (bp1-fd-wp-1e-5) to the first "
                       "event's end", name, found[0].folder)
    # the explicit steps' path against the implicit step on the same mesh
    # and mass: what the explicit steps change
    both = load(work, [("bp1-fd-ie", "implicit-explicit"),
                       ("bp1-fd-implicit-lumped", "implicit, lumped mass")],
                "bp1-fd.implicit-lumped")
    if len(both) == 2:
        record_gaps(record, lambda f: f"bp1-fd.implicit-lumped.ie_{f}",
                    "implicit-explicit against the implicit step "
                    "throughout, both with the lumped mass: first event's "
                    "{text}", first_event(both[0]), first_event(both[1]),
                    "bp1-fd-implicit-lumped", both[1].folder,
                    ("start", "peak", "jump"), 2)

def results_fd_switch(work, record):
    """BP1-FD as shipped (bp1-fd: explicit steps inside the events) to its
    third event: the starts, the first event, the cost and the cost over
    SCycle's wall time (its time.txt from `peers`)."""
    found = load(work, [("bp1-fd", "implicit-explicit")], "bp1-fd.switch")
    if not found:
        return
    ours = found[0]
    a = ours.events(FD_MERGE)
    if len(a) < 3:
        print(f"bp1-fd: {len(a)} of its 3 events (still running or "
              "stopped): no rows written")
        return
    # the second event is not converged in either code (bp1-fd.recurrence):
    # the starts are given, not paired with SCycle's
    record("bp1-fd.switch.starts",
           ", ".join(f"{e.start / YEAR:.2f}" for e in a), "yr",
           "as shipped (explicit steps in the events, lumped mass, Courant "
           "number 0.5): the three events' starts", "bp1-fd", ours.folder)
    first_end = wall_after(os.path.join(ours.folder, "log.txt"),
                           "event 1 ended")
    if first_end is not None:
        record("bp1-fd.switch.first_event_wall",
               f"{first_end // 60} min {first_end % 60:02d}", "s",
               "as shipped: wall time of one core to the first event's end "
               "(the log's progress line after it)", "bp1-fd", ours.folder)
    mine = context_of(work, "bp1-fd", ours.folder)
    timing = os.path.join(work, "scycle-50m", "time.txt")
    if "cpu_s" in mine:
        cpu = int(round(mine["cpu_s"]))
        # README.md's SEAS table: the shipped file's events and cost
        record("bp1-fd.events", f"{len(a)} (to {ours.t[-1] / YEAR:.0f} yr)",
               "", "as shipped: events run (Stop after events = 3)",
               "bp1-fd", ours.folder)
        record("bp1-fd.cost", f"{cpu // 60} min {cpu % 60:02d}", "s",
               "as shipped: CPU time of one core to the third event's end",
               "bp1-fd", ours.folder)
        if os.path.exists(timing):
            theirs = time_v(timing)
            together = side_by_side(os.path.join(work, "bp1-fd.json"),
                                    mine["wall_s"],
                                    os.path.join(work, "scycle-50m"))
            record("bp1-fd.switch.cost_ratio",
                   f"{mine['wall_s'] / theirs['wall_s']:.2f}", "x",
                   "as shipped: wall time over SCycle's to the third event "
                   f"({mine['wall_s']:.0f} against {theirs['wall_s']:.0f} s, "
                   "one core each, "
                   f"{'side by side' if together else 'not side by side'})",
                   "bp1-fd", ours.folder)
    found = load(work, [("scycle-50m", "SCycle 50 m")], "bp1-fd.switch.scycle")
    if found and len(found[0].events(FD_MERGE)) == 3:
        b = found[0].events(FD_MERGE)
        print(catalog.markdown(catalog.compare(a, b), "as shipped",
                               found[0].label))
        record("bp1-fd.switch.scycle_starts",
               ", ".join(f"{e.start / YEAR:.2f}" for e in b), "yr",
               "SCycle at 50 m: the three events' starts", "scycle-50m")
        if os.path.exists(timing):
            record("bp1-fd.peer_cost", *duration(time_v(timing)["wall_s"]),
                   f"SCycle's wall time to its third event "
                   f"({found[0].t[-1] / YEAR:.0f} yr)", "scycle-50m")
        # (README.md's SEAS table: bp1-fd.peak_slip_rate)
        record_gaps(record, lambda f: f"bp1-fd.{GAP_KEY[f]}",
                    "as shipped: first event's {text} against SCycle's",
                    a[0], b[0], "bp1-fd", ours.folder)


def side_by_side(context_file, wall, peer_folder):
    """Whether a run (its JSON context file, written at its end, and its
    wall time [s]) ran within a peer's run (the start and end lines of
    the peer folder's timing.txt) for at least 90 % of its wall time."""
    timing = os.path.join(peer_folder, "timing.txt")
    if not (os.path.exists(context_file) and os.path.exists(timing)):
        return False
    stamps = {}
    with open(timing, encoding="utf-8") as f:
        for line in f:
            words = line.split()
            if len(words) == 2 and words[0] in ("start", "end"):
                stamps[words[0]] = datetime.datetime.fromisoformat(
                    words[1]).timestamp()
    if len(stamps) < 2:
        return False
    end = os.path.getmtime(context_file)
    overlap = min(end, stamps["end"]) - max(end - wall, stamps["start"])
    return overlap >= 0.9 * wall


# a first event's fields: (what, unit, scale, digits shown); the names of
# the rows of their differences from SCycle's
FIRST_EVENT = {"start": ("start", "yr", YEAR, 3),
               "peak": ("peak slip rate", "m/s", 1, 2),
               "jump": ("surface slip", "m", 1, 4)}
GAP_KEY = {"start": "first_event", "peak": "peak_slip_rate",
           "jump": "surface_slip"}


def record_gaps(record, key, what, ours, theirs, name, folder=None,
                fields=("start", "peak", "jump"), digits=2):
    """Rows key(field) [%]: a first event's fields against another's,
    described as `what` (with {text}, the field) and both values."""
    for field in fields:
        text, unit, scale, shown = FIRST_EVENT[field]
        x, y = getattr(ours, field) / scale, getattr(theirs, field) / scale
        record(key(field), f"{100 * relative(x, y):+.{digits}f}", "%",
               what.format(text=text) + f" ({x:.{shown}f} against "
               f"{y:.{shown}f} {unit})", name, folder)


def wall_after(log, text):
    """The wall time [s] of the first progress line ('wall 0h05m41s') after
    the first line of `log` that contains `text`; None if there is none."""
    seen = False
    with open(log) as f:
        for line in f:
            seen = seen or text in line
            match = re.search(r"wall (\d+)h(\d+)m(\d+)s", line)
            if seen and match:
                h, m, s = (int(g) for g in match.groups())
                return 3600 * h + 60 * m + s
    return None


def first_event(s):
    return s.events(FD_MERGE)[0]


def results_fd(work, record):
    """BP1-FD's rows of the implicit step throughout (bp1-fd-implicit):
    rsfcycle against SCycle, and each on its grids."""
    found = load(work, [("scycle-50m", "SCycle 50 m"),
                        ("bp1-fd-implicit", "50 m")], "bp1-fd")
    if len(found) == 2:
        peer, ours = found
        a, b = ours.events(FD_MERGE), peer.events(FD_MERGE)
        print(catalog.markdown(catalog.compare(a, b), ours.label, peer.label))
        p = run.parameters(ours.folder)
        record("bp1-fd.cells", f"{element_size(ours.folder):g}", "m",
               "fault cells (bulk Refinement distance = "
               f"{p.get('Mesh/Refinement distance', '?')})",
               "bp1-fd-implicit", ours.folder)
        record("bp1-fd.implicit_events",
               f"{len(a)} (to {ours.t[-1] / YEAR:.0f} yr)",
               "", f"events run (Stop after events = "
               f"{p.get('Stop after events', '?')})", "bp1-fd-implicit",
               ours.folder)
        size = element_size(peer.folder)
        record("bp1-fd.peer", f"SCycle at {size:.0f} m", "",
               f"peer: SCycle {scycle.COMMIT[:7]} with scycle.patch",
               "bp1-fd", ours.folder)
        record_gaps(record, lambda f: f"bp1-fd.implicit_{GAP_KEY[f]}",
                    "implicit step throughout: first event's {text} "
                    "against SCycle", a[0], b[0], "bp1-fd-implicit",
                    ours.folder)
        mine = context_of(work, "bp1-fd-implicit", ours.folder)
        timing = os.path.join(work, "scycle-50m", "time.txt")
        if os.path.exists(timing):
            theirs = time_v(timing)
            record("bp1-fd.peer_cost", *duration(theirs["wall_s"]),
                   f"SCycle's wall time to its third event ("
                   f"{peer.t[-1] / YEAR:.0f} yr)", "scycle-50m")
            if "cpu_s" in mine and "cpu_s" in theirs:
                record("bp1-fd.cost_ratio",
                       f"{mine['cpu_s'] / theirs['cpu_s']:.2f}", "x",
                       "rsfcycle's CPU time over SCycle's to the third "
                       "event", "bp1-fd-implicit", ours.folder)
        if "cpu_s" in mine:
            cpu = int(round(mine["cpu_s"]))
            cores = int(mine["cores"])
            record("bp1-fd.implicit_cost",
                   f"{cpu // 3600} h {cpu % 3600 // 60} min "
                   "CPU", "", "CPU time" + (" of one core" if cores == 1
                                            else f" of {cores} ranks") +
                   f" to the third event's end ({cpu} s)", "bp1-fd-implicit",
                   ours.folder)
    found = load(work, [("bp1-fd-implicit", "50 m"), ("bp1-fd-25m", "25 m")],
                 "bp1-fd.25m")
    if len(found) == 2:
        coarse, fine = (s.events(FD_MERGE) for s in found)
        rows = catalog.compare(fine, coarse)
        for key, field, text in (
                ("first_event", "start", "start"),
                ("peak_slip_rate", "peak", "peak slip rate"),
                ("surface_slip", "jump", "surface slip")):
            record(f"bp1-fd.25m.{key}", f"{100 * rows[0][field]:+.2f}", "%",
                   f"25 m against 50 m: first event's {text}", "bp1-fd-25m",
                   found[1].folder)
        gaps = [r["interval"] for r in rows[:2] if r["interval"] is not None]
        if gaps:
            record("bp1-fd.25m.intervals", ", ".join(signed(g) for g in gaps),
                   "%", "25 m against 50 m: second and third intervals",
                   "bp1-fd-25m", found[1].folder)
    found = load(work, [(n, n) for n in ("bp1-fd-implicit", "bp1-fd-d3",
                                         "bp1-fd-d5",
                                         "bp1-fd-d6")], "bp1-fd.bulk")
    if len(found) > 1 and found[0].label == "bp1-fd-implicit":
        catalogues = [s.events(FD_MERGE) for s in found]
        starts = [c[0].start for c in catalogues]
        record("bp1-fd.bulk.first_event",
               f"{100 * (max(starts) - min(starts)) / starts[0]:.2f}", "%",
               f"first event's start over {len(found)} bulk meshes",
               "bp1-fd-implicit", found[0].folder)
        second = [(c[1].start - c[0].start) / YEAR for c in catalogues
                  if len(c) > 1]
        if len(second) == len(found):
            record("bp1-fd.bulk.second_interval",
                   f"{min(second):.0f} – {max(second):.0f}", "yr",
                   f"second interval over {len(found)} bulk meshes "
                   f"(shipped: {second[0]:.2f} yr)", "bp1-fd-implicit",
                   found[0].folder)
    found = load(work, [("scycle-50m", "50 m"), ("scycle-100m", "100 m")],
                 "bp1-fd.scycle")
    if len(found) == 2:
        fine, coarse = (first_event(s) for s in found)
        record("bp1-fd.scycle.first_event_grid",
               f"{100 * abs(relative(coarse.start, fine.start)):.2f}", "%",
               "SCycle's first event's start, 100 m against 50 m",
               "scycle-100m")
        record_gaps(record, lambda f: f"bp1-fd.scycle.{f}_grid",
                    "SCycle's first event's {text}, 100 m against 50 m",
                    coarse, fine, "scycle-100m", None, ("peak", "jump"))
    for name, key, text in (
            ("scycle-50m-3e-5", "second_interval", "SCycle 50 m, wave "
             "equation from 0.03 mm/s: second interval"),
            ("scycle-100m", "second_interval_100m", "SCycle 100 m, wave "
             "equation from 0.1 mm/s: second interval")):
        found = load(work, [(name, name)], "bp1-fd.scycle." + key)
        if found and len(found[0].events(FD_MERGE)) > 1:
            e = found[0].events(FD_MERGE)
            record(f"bp1-fd.scycle.{key}",
                   f"{(e[1].start - e[0].start) / YEAR:.2f}", "yr", text,
                   name)
    # each code one step looser (`cost`): its starts beside the shipped
    # tolerance's (bp1-fd.switch.starts, bp1-fd.switch.scycle_starts)
    for name, key, label in (
            ("scycle-50m-tol1e-6", "bp1-fd.scycle.tol1e-6",
             "SCycle at 50 m, timeStepTol 1e-6 (shipped 1e-7)"),
            ("bp1-fd-tol3e-5", "bp1-fd.tol3e-5",
             "as shipped at delta 3e-5 (shipped 1e-5)")):
        found = load(work, [(name, name)], key)
        cpu = cpu_of(work, name)
        if found and len(found[0].events(FD_MERGE)) == 3 and cpu:
            record(f"{key}_starts", ", ".join(
                f"{e.start / YEAR:.2f}" for e in found[0].events(FD_MERGE)),
                "yr", f"{label}: the three events' starts", name,
                found[0].folder)
            record(f"{key}_cpu", *duration(cpu),
                   f"{label}: CPU time to the third event", name,
                   found[0].folder)


def cpu_of(work, name):
    """The CPU time [s] of a run in WORK: a peer's from its time.txt, an
    rsfcycle run's from its JSON file; None if unknown."""
    if name in PEERS:
        timing = os.path.join(peer_folder(work, name), "time.txt")
        return (time_v(timing).get("cpu_s") if os.path.exists(timing)
                else None)
    return context_of(work, name).get("cpu_s")


def results_bp2(work, record):
    """BP2-QD's rows against QDYN."""
    found = load(work, [("qdyn-bp2", "QDYN"), ("bp2-qd", "12.5 m")], "bp2-qd")
    if len(found) == 2:
        peer, ours = found
        a, b = ours.events(), peer.events()
        rows = catalog.compare(a, b)
        print(catalog.markdown(rows, ours.label, peer.label))
        record("bp2-qd.cells", f"{element_size(ours.folder):g}", "m",
               "fault cells (Green's-function method, 800 km body)",
               "bp2-qd", ours.folder)
        record("bp2-qd.events", f"{len(a)} in {ours.t[-1] / YEAR:.0f} yr", "",
               f"events above 1 mm/s (QDYN: {len(b)})", "bp2-qd", ours.folder)
        n, length = qdyn.read_mesh(peer_folder(work, "qdyn-bp2"))
        record("bp2-qd.peer", f"QDYN at {length / n:.1f} m", "",
               f"peer: QDYN {qdyn.COMMIT[:7]}, N = {n}", "bp2-qd",
               ours.folder)
        sa, sb = summary(a, 9), summary(b, 9)
        record("bp2-qd.recurrence",
               f"{100 * relative(sa['interval'], sb['interval']):+.2f}", "%",
               f"mean interval after the first 9 events against QDYN "
               f"({sa['interval'] / YEAR:.2f} against "
               f"{sb['interval'] / YEAR:.2f} yr)", "bp2-qd", ours.folder)
        record("bp2-qd.first_event", f"{100 * rows[0]['start']:+.2f}", "%",
               f"first event's start against QDYN ({a[0].start / YEAR:.2f} "
               f"against {b[0].start / YEAR:.2f} yr)", "bp2-qd", ours.folder)
        record("bp2-qd.peak_slip_rate", span([r["peak"] for r in rows]), "%",
               "every event's peak slip rate against QDYN", "bp2-qd",
               ours.folder)
        record("bp2-qd.starts", span([r["start"] for r in rows]), "%",
               "every event's start against QDYN", "bp2-qd", ours.folder)
        record("bp2-qd.intervals", span([r["interval"] for r in rows
                                         if r["interval"] is not None]), "%",
               "every interval against QDYN", "bp2-qd", ours.folder)
        full = [r["jump"] for r, e in zip(rows, b) if e.jump > 0.1]
        if full:
            record("bp2-qd.surface_slip", span(full), "%", "surface slip of "
                   "the full ruptures against QDYN", "bp2-qd", ours.folder)
        wall = run.wall_time(ours.folder)
        if wall:
            record("bp2-qd.cost", *duration(wall), "wall time, 1200 years",
                   "bp2-qd", ours.folder)
        timing = os.path.join(peer_folder(work, "qdyn-bp2"), "time.txt")
        if os.path.exists(timing):
            record("bp2-qd.peer_cost", *duration(time_v(timing)["wall_s"]),
                   f"QDYN's wall time, 1200 years at {length / n:.1f} m",
                   "qdyn-bp2")
    found = load(work, [("qdyn-bp2", "QDYN"), ("bp2-qd-25m", "25 m")],
                 "bp2-qd.25m")
    if len(found) == 2:
        peer, ours = found
        a, b = ours.events(), peer.events()
        rows = catalog.compare(a, b)
        record("bp2-qd.25m.starts", span([r["start"] for r in rows]), "%",
               "25 m on the 400 km body: every event's start against QDYN",
               "bp2-qd-25m", ours.folder)
        sa, sb = summary(a, 9), summary(b, 9)
        record("bp2-qd.25m.settled_cycle",
               f"{100 * relative(sa['interval'], sb['interval']):+.2f}", "%",
               "25 m on the 400 km body: settled cycle against QDYN",
               "bp2-qd-25m", ours.folder)


# ------------------------------------------------------------- figures


def pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def series_figures(runs, out, merge=0.0, recurrence=True):
    """max-slip-rate.png, surface-slip.png and (if `recurrence`)
    recurrence.png: every interval at its event's start, and its
    difference from the first run's interval of the same number (the band
    is ±0.5 %)."""
    plt = pyplot()
    os.makedirs(out, exist_ok=True)
    for name, ylabel in (("max-slip-rate.png", "log10 max slip rate [m/s]"),
                         ("surface-slip.png", "surface slip [m]")):
        fig, ax = plt.subplots(figsize=(9, 4))
        for s in runs:
            y = np.log10(s.v) if name.startswith("max") else s.slip
            ax.plot(s.t / YEAR, y, lw=0.8, label=s.label)
        ax.set_xlabel("time [yr]")
        ax.set_ylabel(ylabel)
        ax.legend()
        fig.tight_layout()
        fig.savefig(os.path.join(out, name), dpi=120)
        plt.close(fig)
    if not recurrence:
        return
    fig, (ax, ax_diff) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    reference = np.diff([e.start for e in runs[0].events(merge)]) / YEAR
    for s in runs:
        starts = np.array([e.start for e in s.events(merge)]) / YEAR
        gaps = np.diff(starts)
        line, = ax.plot(starts[1:], gaps, "o-", ms=3, lw=0.8, label=s.label)
        n = min(len(gaps), len(reference))
        if s is not runs[0] and n:
            ax_diff.plot(starts[1:n + 1], 100 * (gaps[:n] / reference[:n] - 1),
                         "o-", ms=3, lw=0.8, color=line.get_color())
    ax.set_ylabel("interval to the event before [yr]")
    ax.legend()
    ax_diff.axhspan(-0.5, 0.5, color="0.9")
    ax_diff.axhline(0, color="0.5", lw=0.5)
    ax_diff.set_ylabel(f"against {runs[0].label} [%]")
    ax_diff.set_xlabel("event start [yr]")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "recurrence.png"), dpi=120)
    plt.close(fig)


def slip_contours(s, path):
    """The slip along depth of devol.dat: blue between events (every 5
    years), red during them (every second)."""
    plt = pyplot()
    depth, t, logv, slip = seas.profile(os.path.join(s.folder, "devol.dat"))
    fig, ax = plt.subplots(figsize=(6, 5))
    for k in range(len(t)):
        ax.plot(slip[k], depth / 1e3, lw=0.4,
                color="tab:red" if logv[k] > np.log10(THRESHOLD)
                else "tab:blue")
    ax.invert_yaxis()
    ax.set_xlabel("slip [m]")
    ax.set_ylabel("depth [km]")
    ax.set_title(f"{s.label}: slip every 5 yr (blue) and 1 s in events "
                 f"(red), to {t[-1] / YEAR:.0f} yr", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def two_panels(curves, xlabel, title, path):
    """log10 slip rate above, shear stress below; curves (label, t,
    log10 V, stress)."""
    plt = pyplot()
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    for label, t, logv, tau in curves:
        a1.plot(t, logv, lw=0.8, label=label)
        a2.plot(t, tau, lw=0.8, label=label)
    a1.set_ylabel("log10 slip rate [m/s]")
    a2.set_ylabel("shear stress [MPa]")
    a2.set_xlabel(xlabel)
    a1.set_title(title)
    a1.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def station_figures(runs, out, code="075"):
    """station-CODE.png over the whole run and first-event-CODE.png from
    30 s before to 200 s after each run's first rise above 1 mm/s."""
    os.makedirs(out, exist_ok=True)
    depth = int(code) / 10
    whole, first = [], []
    for s in runs:
        t, logv, tau = s.station(code)
        whole.append((s.label, t / YEAR, logv, tau))
        start = s.t[np.argmax(s.v > THRESHOLD)]
        near = (t > start - 30) & (t < start + 200)
        first.append((s.label, t[near] - start, logv[near], tau[near]))
    two_panels(whole, "time [yr]", f"station at {depth:.1f} km depth",
               os.path.join(out, f"station-{code}.png"))
    two_panels(first, "time from the first event's start (max V > 1 mm/s) "
               "[s]", f"first event, station at {depth:.1f} km depth",
               os.path.join(out, f"first-event-{code}.png"))


def work_precision(runs, reference, path):
    """BP1-FD's first event (start, peak slip rate, surface slip) against
    the wall time of runs that stop after it; SCycle's as dashed lines."""
    plt = pyplot()
    fig, axes = plt.subplots(1, 3, figsize=(13, 4))
    keys = (("start", "first event's start [yr]", YEAR),
            ("peak", "peak slip rate [m/s]", 1),
            ("jump", "surface slip of the first event [m]", 1))
    for ax, (field, name, scale) in zip(axes, keys):
        for s in runs:
            wall = run.wall_time(s.folder) / 60
            value = getattr(first_event(s), field) / scale
            ax.plot(wall, value, "o")
            ax.annotate(s.label, (wall, value), fontsize=7, xytext=(3, 3),
                        textcoords="offset points")
        if reference is not None:
            ax.axhline(getattr(first_event(reference), field) / scale,
                       color="k", lw=0.8, ls="--", label=reference.label)
            ax.legend(fontsize=7)
        ax.set_xscale("log")
        ax.set_xlabel("wall time to the event's end [min]")
        ax.set_ylabel(name)
    fig.suptitle("BP1-FD, elastic, generalized-α: work against precision")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def cost_scycle(work, record):
    """BP1-FD at equal accuracy: SCycle's scycle-50m (timeStepTol 1e-7) and
    scycle-50m-tol1e-6 (`peers`), rsfcycle's bp1-fd (delta 1e-5) and
    bp1-fd-tol3e-5 (`runs`). For each code the loosest run whose three
    events start within 0.01 % of its tightest run's is taken; the CPU
    times there give the rows bp1-fd.equal_*. Nothing (False) when a run
    is missing."""
    families = {
        "SCycle": {"scycle-50m": "1e-7", "scycle-50m-tol1e-6": "1e-6"},
        "rsfcycle": {"bp1-fd": "1e-5", "bp1-fd-tol3e-5": "3e-5"}}
    chosen = {}
    for code, tolerance in families.items():
        runs = []
        for name, tol in tolerance.items():
            found = load(work, [(name, name)], "cost")
            cpu = cpu_of(work, name)
            if not found or not cpu:
                print(f"{code}: no finished run {name} in {work}")
                return False
            runs.append((name, tol, found[0].events(FD_MERGE), cpu))
        chosen[code], states = cheapest_unchanged(runs)
        print(equal_table(code, states))
        worst = max((abs(relative(a.start, b.start))
                     for a, b in zip(runs[1][2], runs[0][2])), default=0)
        record(f"bp1-fd.equal_{code.lower()}", chosen[code][1], "",
               f"{code}'s loosest tolerance of {runs[0][1]}, {runs[1][1]} "
               "with its three events unchanged (starts within 0.01 %); at "
               f"{runs[1][1]} they move by up to {100 * worst:.2f} %",
               chosen[code][0])
    ours, peer = chosen["rsfcycle"], chosen["SCycle"]
    record("bp1-fd.equal_ratio", f"{ours[3] / peer[3]:.2f}", "x",
           f"rsfcycle's CPU time over SCycle's to the third event, each at "
           f"its loosest unchanged tolerance ({ours[3]:.0f} against "
           f"{peer[3]:.0f} s)", ours[0])
    return True


def cmd_cost(args):
    """rsfcycle's cost against QDYN's at equal accuracy over 1000 years of
BP1-QD: the runs bp1-qd-1000yr-DELTA (`runs`) and qdyn-bp1-1000yr-ACC
(`peers`; run the two sets side by side, one core each). For each code the
run at the tightest tolerance is the reference; the loosest one whose
catalogue has the same events, every start within 0.01 % of the
reference's, is taken, and the ratio of the two codes' wall times there
goes to results.csv (bp1-qd.equal_*). Then SCycle's BP1-FD the same way
(cost_scycle)."""
    scycle_done = cost_scycle(args.work, Recorder(args.work))
    families = {
        "rsfcycle": [n for n in RUNS if n.startswith("bp1-qd-1000yr-")],
        "QDYN": [n for n in PEERS if n.startswith("qdyn-bp1-1000yr-")]}
    chosen = {}
    for code, names in families.items():
        # tightest first: the tolerance follows "1000yr-"
        names = sorted(names, key=lambda n: float(n.split("1000yr-")[1]))
        found = []
        for name in names:
            series = load(args.work, [(name, name)], "cost")
            if series:
                found.append((name, series[0]))
        if not found:
            print(f"run.py: no {code} run of `cost` in {args.work}",
                  file=sys.stderr)
            return 0 if scycle_done else 2
        reference = found[0][1].events()
        for name, series in found:
            folder = (peer_folder(args.work, name) if name in PEERS else
                      os.path.join(args.work, name))
            wall = (time_v(os.path.join(folder, "time.txt"))["wall_s"]
                    if name in PEERS else run.wall_time(folder))
            worst = unchanged(series.events(), reference)
            state = ("reference" if name == found[0][0] else "unchanged, "
                     f"starts within {100 * worst:.4f} %" if worst is not None
                     else "changed")
            print(f"{code:8} {name:26} {len(series.events()):3d} events  "
                  f"wall {wall:8.1f} s  {state}")
            if worst is not None or name == found[0][0]:
                chosen[code] = (name, wall, folder)
    (ours, ours_wall, folder), (peer, peer_wall, _) = (chosen["rsfcycle"],
                                                       chosen["QDYN"])
    ratio = ours_wall / peer_wall
    print(f"equal accuracy: {ours} over {peer}: {ratio:.2f}x")
    record = Recorder(args.work)
    record("bp1-qd.equal_rsfcycle", RUNS[ours][1]["Time stepping/Tolerance"],
           "", "rsfcycle's loosest step tolerance with its 1000-year "
           "catalogue unchanged (starts within 0.01 %)", ours, folder)
    record("bp1-qd.equal_qdyn", PEERS[peer][2][-1], "",
           "QDYN's loosest ACC with its 1000-year catalogue unchanged", peer)
    record("bp1-qd.equal_wall", *duration(ours_wall),
           f"rsfcycle's wall time, 1000 years at delta "
           f"{RUNS[ours][1]['Time stepping/Tolerance']}", ours, folder)
    record("bp1-qd.equal_peer_wall", *duration(peer_wall),
           f"QDYN's wall time, 1000 years at ACC {PEERS[peer][2][-1]}", peer)
    record("bp1-qd.equal_ratio", f"{ratio:.2f}", "x",
           "rsfcycle's wall time over QDYN's at equal accuracy (1000 yr, "
           "each at its loosest unchanged tolerance)", ours, folder)
    return 0


def cmd_figures(args):
    """Redraw the README's figures (figures/, figures/fd-elastic,
figures/fd-scycle, figures/bp2) from the run folders in WORK; a figure
whose runs are missing is skipped with a line."""
    work, out = args.work, os.path.join(HERE, "figures")

    def drawn(runs, least, what):
        ok = len(runs) >= least
        print(f"{what}: " + ("drawn from " + ", ".join(s.label for s in runs)
                             if ok else "skipped"))
        return ok

    runs_ = load(work, [("qdyn-bp1", "QDYN"), ("bp1-qd", "25 m"),
                        ("bp1-qd-50m", "50 m"),
                        ("bp1-qd-volume", "volume method 50 m")], "figures")
    if drawn(runs_, 2, "figures/{max-slip-rate,surface-slip,recurrence}"):
        series_figures(runs_, out)
    for name, label in (("bp1-qd-50m", "QD-50m"), ("bp1-qd-200m", "QD-200m"),
                        ("bp1-fd", "FD-50m"), ("bp1-fd-200m", "FD-200m")):
        runs_ = load(work, [(name, label)], "figures")
        if drawn(runs_, 1, f"figures/slip-contours-{label}.png"):
            slip_contours(runs_[0], os.path.join(
                out, f"slip-contours-{label}.png"))
    runs_ = load(work, [("bp1-qd", "QD 25 m"), ("bp1-fd", "FD 50 m")],
                 "figures")
    if drawn(runs_, 1, "figures/{station,first-event}-075"):
        station_figures(runs_, out)
    # fd-elastic: Refinement distance 3 against the shipped 4
    sub = os.path.join(out, "fd-elastic")
    runs_ = load(work, [("bp1-fd-implicit", "distance 4"),
                        ("bp1-fd-d3", "distance 3")],
                 "figures/fd-elastic")
    if drawn(runs_, 2, "figures/fd-elastic/"):
        series_figures(runs_, sub, FD_MERGE, recurrence=False)
        station_figures(runs_, sub)
        slip_contours(runs_[1], os.path.join(
            sub, "slip-contours-FD-50m-elastic.png"))
    points = load(work, [(n, n[len("bp1-fd-wp-"):]) for n in RUNS
                         if n.startswith("bp1-fd-wp-")], "work-precision")
    if drawn(points, 1, "figures/fd-elastic/work-precision.png"):
        reference = load(work, [("scycle-50m", "SCycle 50 m")], "reference")
        os.makedirs(sub, exist_ok=True)
        work_precision(points, reference[0] if reference else None,
                       os.path.join(sub, "work-precision.png"))
    # fd-scycle: BP1-FD against SCycle
    sub = os.path.join(out, "fd-scycle")
    runs_ = load(work, [("scycle-50m", "SCycle 50 m"),
                        ("bp1-fd-implicit", "50 m"), ("bp1-fd-25m", "25 m")],
                 "figures/fd-scycle")
    if drawn(runs_, 2, "figures/fd-scycle/"):
        series_figures(runs_, sub, FD_MERGE)
        station_figures(runs_, sub)
    for name, label in (("bp1-fd-25m", "FD-25m"),
                        ("scycle-50m", "SCycle-50m")):
        runs_ = load(work, [(name, label)], "figures/fd-scycle")
        if drawn(runs_, 1, f"figures/fd-scycle/slip-contours-{label}.png"):
            os.makedirs(sub, exist_ok=True)
            slip_contours(runs_[0], os.path.join(
                sub, f"slip-contours-{label}.png"))
    runs_ = load(work, [("qdyn-bp2", "QDYN"), ("bp2-qd", "12.5 m"),
                        ("bp2-qd-25m", "25 m, 400 km body")], "figures/bp2")
    if drawn(runs_, 2, "figures/bp2/"):
        series_figures(runs_, os.path.join(out, "bp2"))
    return 0


# -------------------------------------------------------------- cycles


def cmd_cycles(args):
    """log10 V [m/s] at the fault stations --depths, --lags years after
the start of each of the first --cycles events: QDYN's (qdyn-bp1) and
each named run's (default bp1-qd, bp1-qd-50m)."""
    work = args.work
    peer = load(work, [("qdyn-bp1", "QDYN")], "cycles")
    ours = load(work, [(n, n) for n in args.names], "cycles")
    if not peer or not ours:
        return 2
    depths = [float(x) for x in args.depths.split(",")]
    lags = [float(x) for x in args.lags.split(",")]
    path = os.path.join(work, "qdyn", PEERS["qdyn-bp1"][3] + "_series.csv")
    columns = [(peer[0], {d: qdyn.read_station(path, d)[:2] for d in depths})]
    for s in ours:
        columns.append((s, {d: s.station("%03d" % round(10 * d))[:2]
                            for d in depths}))
    print("log10 V [m/s] at the fault stations, years after each event's "
          "start; columns: " + ", ".join(s.label for s, _ in columns))
    for k in range(args.cycles):
        for d in depths:
            for lag in lags:
                cells = []
                for s, stations in columns:
                    starts = [e.start for e in s.events()]
                    t, logv = stations[d]
                    at = starts[k] + lag * YEAR if k < len(starts) else np.inf
                    cells.append("%8.3f" % np.interp(at, t, logv)
                                 if at <= t[-1] else "       -")
                print("cycle %d  %5.1f km  %5.1f yr  %s"
                      % (k + 1, d, lag, " ".join(cells)))
    return 0


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="benchmarks/seas-bp1/run.py", description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)

    raw = argparse.RawDescriptionHelpFormatter

    def stage(function, summary, *options):
        p = sub.add_parser(function.__name__[len("cmd_"):], help=summary,
                           description=function.__doc__,
                           formatter_class=raw)
        p.add_argument("--work", default=os.path.join(HERE, "runs"),
                       help="the run folders (default: "
                       "benchmarks/seas-bp1/runs, not tracked)")
        for flags, settings in options:
            p.add_argument(*flags, **settings)
        p.set_defaults(func=function)

    names = ("names",), {"nargs": "*", "metavar": "NAME"}
    listing = ("--list",), {"action": "store_true",
                            "help": "the names and their measured cost"}
    stage(cmd_runs, "rsfcycle's runs into WORK/NAME", names, listing,
          (("--all",), {"action": "store_true", "help": "every run"}),
          (("--build",), {"default": os.path.join(ROOT, "build"),
                          "help": "the build folder or the rsfcycle binary "
                          "(default build/)"}),
          (("--ranks",), {"type": int, "default": 1,
                          "help": "MPI ranks (default 1)"}))
    stage(cmd_peers, "QDYN's and SCycle's runs", names, listing,
          (("--qdyn-src",), {"help": "QDYN clone (default: $QDYN_SRC)"}),
          (("--scycle-src",), {"help": "SCycle clone (default: "
                               "$SCYCLE_SRC)"}))
    stage(cmd_results, "results.csv from the run folders")
    stage(cmd_cost, "rsfcycle against QDYN at equal accuracy")
    stage(cmd_figures, "the README's figures from the run folders")
    stage(cmd_cycles, "BP1-QD cycle by cycle against QDYN",
          (("names",), {"nargs": "*", "default": ["bp1-qd", "bp1-qd-50m"],
                        "metavar": "NAME"}),
          (("--depths",), {"default": "12.5,15", "help": "[km]"}),
          (("--lags",), {"default": "20,40,60,66,70,74", "help": "[yr]"}),
          (("--cycles",), {"type": int, "default": 6}))
    args = parser.parse_args(argv)
    args.work = os.path.abspath(args.work)
    return args.func(args)


if __name__ == "__main__":
    sys.exit(main())
