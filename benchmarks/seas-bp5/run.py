#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""SEAS BP5-QD: rsfcycle against HBI at 1 km and 500 m; the figures and
results.csv of benchmarks/seas-bp5/README.md (BP5-FD: benchmarks/seas-bp5-fd).

From the repository's root, with the package on the path:

  PYTHONPATH=python /usr/bin/python3 benchmarks/seas-bp5/run.py COMMAND ...

  runs     prm/seas-bp5-qd.prm into WORK/rsfcycle-1km (2 ranks: the
           operator about 80 s, the 1800 years about 4.5 min); --cells
           500m adds WORK/rsfcycle-500m (Local refinements = 3: the
           operator about 13 min and 18 GiB, the time loop about 3 h)
  peer     HBI (HBI_SRC or --hbi-src) into WORK/hbi-1km, about 7 min on
           one core; --cell 500 into WORK/hbi-500m, about 47 min
  figures  figures/*.png from WORK/rsfcycle-1km, hbi-1km, hbi-500m and
           figures/500m/*.png from rsfcycle-500m and rsfcycle-1km
  results  the event catalogues of the run folders in WORK and their
           differences into results.csv (rsfcycle.results.record)

WORK is --work (default benchmarks/seas-bp5/runs). An event is max V >=
1 mm/s in global.dat (rsfcycle.catalog.detect, runs within an hour
joined); years of 365.25 days; the surface slip is the station
fltst_strk+00dp+00's.
"""

import os
import sys

from rsfcycle.peers import hbi

HERE = os.path.dirname(os.path.abspath(__file__))
STATION = "fltst_strk+00dp+00"
MERGE = 3600.0
# `equal`: the shipped file, its step tolerance, the station, the merge [s]
EQUAL = ("prm/seas-bp5-qd.prm", "1e-5", STATION, MERGE)
CELLS = {"1km": {}, "500m": {"Mesh/Local refinements": 3}}


def runs(args):
    """rsfcycle's runs into --work (1 km: about 6 min on 2 ranks)."""
    for cells in args.cells:
        hbi.run_rsfcycle("prm/seas-bp5-qd.prm", os.path.join(args.work, "rsfcycle-" + cells),
                         CELLS[cells], args.ranks, args.binary)


def folders(work):
    """{label: folder} of the run folders present in WORK."""
    names = ("rsfcycle-1km", "rsfcycle-500m", "hbi-1km", "hbi-500m")
    return {n: os.path.join(work, n) for n in names
            if os.path.isdir(os.path.join(work, n))}


def figures(args):
    """figures/*.png and figures/500m/*.png from the run folders in --work."""
    found = folders(args.work)
    shown = [(n.replace("hbi", "HBI"), found[n]) for n in ("hbi-1km", "hbi-500m", "rsfcycle-1km")
             if n in found]
    if not shown:
        raise FileNotFoundError(f"{args.work}: no run folder")
    hbi.plane_figures(shown, os.path.join(HERE, "figures"))
    fine = [(n, found[n]) for n in ("rsfcycle-500m", "rsfcycle-1km") if n in found]
    if "rsfcycle-500m" in found:
        hbi.plane_figures(fine, os.path.join(HERE, "figures", "500m"))


def pct(x, digits=2):
    return hbi.signed(100 * x, digits)


def results(args):
    """results.csv from the run folders in --work."""
    found = folders(args.work)
    cat = {}
    for name, folder in found.items():
        cat[name] = hbi.catalogue(folder, STATION, merge=MERGE)
        hbi.print_catalogue(name, cat[name])
    if "rsfcycle-1km" not in cat or "hbi-1km" not in cat:
        raise FileNotFoundError(f"{args.work}: rsfcycle-1km and hbi-1km are needed")
    r1, h1 = cat["rsfcycle-1km"], cat["hbi-1km"]
    s = {n: hbi.sequence(c) for n, c in cat.items()}
    d1 = hbi.differences(r1, h1)
    context, cores = hbi.context_of(found["rsfcycle-1km"])
    fine = "rsfcycle-500m" in cat and "hbi-500m" in cat
    d5 = hbi.differences(cat["rsfcycle-500m"], cat["hbi-500m"]) if fine else None
    yr = hbi.YEAR
    rec = [pct(d1["interval"]) + " % at 1 km"] + ([pct(d5["interval"], 3) + " % at 500 m"]
                                                  if fine else [])
    peak = [pct(d1["peak"], 1) + " % at 1 km"] + ([pct(d5["peak"], 1) + " % at 500 m"]
                                                  if fine else [])
    rows = [
        ("bp5-qd.events", f"{len(r1)} in 1800 yr", "", "events (max V ≥ 1 mm/s); HBI: "
         + " and ".join(f"{len(cat[n])} at {c}" for n, c in (("hbi-1km", "1 km"), ("hbi-500m", "500 m")) if n in cat)),
        ("bp5-qd.recurrence", ", ".join(rec), "", "mean interval after the first event "
         f"against HBI at the same cells (1 km: {s['rsfcycle-1km']['interval'] / yr:.2f} "
         f"against {s['hbi-1km']['interval'] / yr:.2f} yr)"),
        ("bp5-qd.peak_slip_rate", ", ".join(peak), "", "median peak slip rate against HBI at "
         f"the same cells (1 km: {s['rsfcycle-1km']['peak']:.3f} against "
         f"{s['hbi-1km']['peak']:.3f} m/s)"),
        ("km1.second_event", pct(d1["second"]), "%", "1 km: second event against HBI 1 km, "
         f"{s['rsfcycle-1km']['second'] / yr:.2f} against {s['hbi-1km']['second'] / yr:.2f} yr"),
        ("km1.first_peak", pct(d1["first_peak"], 1), "%", "1 km: first event's peak slip rate, "
         f"{r1[0]['peak']:.3f} against {h1[0]['peak']:.3f} m/s"),
        ("km1.surface_slip", pct(d1["slip"], 1), "%", "1 km: surface slip at x2 = 0, median, "
         f"{s['rsfcycle-1km']['slip']:.3f} against {s['hbi-1km']['slip']:.3f} m (HBI: its top "
         "cell's centre, 0.5 km deep)"),
        ("km1.mw", f"{d1['mw']:+.4f}", "", f"1 km: Mw, {s['rsfcycle-1km']['mw']:.3f} against "
         f"{s['hbi-1km']['mw']:.3f}"),
    ]
    wall, loop, operator = hbi.rsfcycle_times(found["rsfcycle-1km"])
    if wall:
        rows.append(("bp5-qd.cost", hbi.duration(wall), "", "1800 years at 1 km, the whole run"))
    if loop:
        rows.append(("cost.time_loop", f"{loop:.1f}", "s", "time loop, 1800 years at 1 km"))
    if operator:
        rows.append(("cost.operator", f"{operator:.0f}", "s", "operator build at 1 km"))
    if "hbi-500m" in cat:
        rows.append(("km1.recurrence_hbi500m",
                     pct(s["rsfcycle-1km"]["interval"] / s["hbi-500m"]["interval"] - 1, 1), "%",
                     f"1 km: recurrence against HBI 500 m ({s['hbi-500m']['interval'] / yr:.2f} yr)"))
    hbi_wall, hbi_cpu = hbi.hbi_time(found["hbi-1km"])
    hbi.record(HERE, rows, context, cores)
    if hbi_wall:
        hbi.record(HERE, [("cost.hbi", f"{hbi_wall:.0f}", "s", "HBI's whole run at 1 km "
                           f"({hbi_cpu:.0f} s CPU)")], *hbi.context_of(found["hbi-1km"]))
    if fine:
        r5 = found["rsfcycle-500m"]
        s5, h5 = s["rsfcycle-500m"], s["hbi-500m"]
        rows = [
            ("m500.second_event", pct(d5["second"], 3), "%", "500 m: second event against HBI "
             f"500 m, {s5['second'] / yr:.3f} against {h5['second'] / yr:.3f} yr"),
            ("m500.recurrence", pct(d5["interval"], 3), "%", "500 m: mean interval after the "
             f"first against HBI 500 m, {s5['interval'] / yr:.3f} against {h5['interval'] / yr:.2f} yr"),
            ("m500.peak", pct(d5["peak"], 1), "%", "500 m: median peak slip rate against HBI "
             f"500 m, {s5['peak']:.4f} against {h5['peak']:.3f} m/s"),
            ("m500.surface_slip", pct(d5["slip"]), "%", "500 m: surface slip at x2 = 0 against "
             f"HBI 500 m, {s5['slip']:.3f} against {h5['slip']:.3f} m"),
            ("m500.recurrence_hbi1km", pct(s5["interval"] / s["hbi-1km"]["interval"] - 1), "%",
             f"500 m: recurrence against HBI 1 km ({s['hbi-1km']['interval'] / yr:.2f} yr)"),
            ("m500.own_1km", pct(s["rsfcycle-1km"]["interval"] / s5["interval"] - 1), "%",
             "rsfcycle's 1 km recurrence against its own 500 m run"),
        ]
        _, loop, operator = hbi.rsfcycle_times(r5)
        if operator:
            rows.append(("m500.operator", f"{operator:.0f}", "s", "500 m: operator build"))
        if loop:
            rows.append(("m500.time_loop", hbi.duration(loop), "", "500 m: time loop over "
                         "1800 years"))
        hbi.record(HERE, rows, *hbi.context_of(r5))


def cells(p):
    p.add_argument("--cells", nargs="+", choices=sorted(CELLS), default=["1km"],
                   help="1km (the shipped file), 500m (Local refinements = 3)")


def main(argv=None):
    return hbi.driver(__doc__, HERE, "bp5", {
        "runs": runs, "peer": None, "figures": figures, "results": results},
        {"runs": cells}, argv=argv, equal=EQUAL)


if __name__ == "__main__":
    sys.exit(main())
