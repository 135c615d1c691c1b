#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""SEAS BP4-QD: rsfcycle against HBI at 1 km over 1000 years; the figures
and results.csv of benchmarks/seas-bp4/README.md.

From the repository's root, with the package on the path:

  PYTHONPATH=python /usr/bin/python3 benchmarks/seas-bp4/run.py COMMAND ...

  runs     prm/seas-bp4-qd.prm into WORK/rsfcycle-1km on 2 ranks: the
           operator about 4 min, the 1000 years about 8 min (the mesh
           prm/meshes/seas-bp4.msh is made by quickstart.sh)
  peer     HBI (HBI_SRC or --hbi-src) into WORK/hbi-1km, about 15 min on
           one core; --cell 2000, --eps 1e-8 for its own checks
  figures  figures/*.png from WORK/hbi-1km and WORK/rsfcycle-1km
  results  the event catalogues of both and their differences into
           results.csv (rsfcycle.results.record)

WORK is --work (default benchmarks/seas-bp4/runs). An event is max V >=
1 mm/s in global.dat (rsfcycle.catalog.detect, runs within an hour
joined); years of 365.25 days; the slip is the station
fltst_strk+000dp+000's; the settled interval is the mean of the last
three.
"""

import os
import sys

from rsfcycle.peers import hbi

HERE = os.path.dirname(os.path.abspath(__file__))
STATION = "fltst_strk+000dp+000"
# `equal`: the shipped file, its step tolerance, the station, the merge [s]
EQUAL = ("prm/seas-bp4-qd.prm", "1e-5", STATION, 3600.0)


def runs(args):
    """rsfcycle's run into --work (about 12 min on 2 ranks)."""
    hbi.run_rsfcycle("prm/seas-bp4-qd.prm", os.path.join(args.work, "rsfcycle-1km"),
                     {}, args.ranks, args.binary)


def pair(work):
    """The run folders rsfcycle-1km and hbi-1km of WORK."""
    ours, peer = (os.path.join(work, n) for n in ("rsfcycle-1km", "hbi-1km"))
    for folder in (ours, peer):
        if not os.path.isdir(folder):
            raise FileNotFoundError(f"{folder}: no run folder (run.py runs, run.py peer)")
    return ours, peer


def figures(args):
    """figures/*.png from the run folders in --work."""
    ours, peer = pair(args.work)
    hbi.plane_figures([("HBI-1km", peer), ("rsfcycle-1km", ours)],
                      os.path.join(HERE, "figures"))


def results(args):
    """results.csv from the run folders in --work."""
    ours, peer = pair(args.work)
    a, b = hbi.catalogue(ours, STATION, merge=3600.0), hbi.catalogue(peer, STATION, merge=3600.0)
    hbi.print_catalogue("rsfcycle-1km", a)
    hbi.print_catalogue("hbi-1km", b)
    for name, events in (("rsfcycle", a), ("HBI", b)):
        print(f"{name} intervals [yr]: " + ", ".join(
            f"{x / hbi.YEAR:.2f}" for x in hbi.sequence(events)["intervals"]))
    rows = [("bp4-qd.events", f"{len(a)} in 1000 yr", "", f"events (max V ≥ 1 mm/s); HBI: {len(b)}")]
    rows += hbi.compare_rows(a, b, {
        "bp4-qd.recurrence": ("settled", "settled interval (mean of the last three) against HBI"),
        "bp4-qd.peak_slip_rate": ("peak", "peak slip rate, median after the first event"),
        "cmp.first_event_mw": ("first_mw", "first (imposed) event's Mw against HBI"),
        "cmp.first_event_peak": ("first_peak", "first event's peak slip rate against HBI"),
        "cmp.second_event": ("second", "second event against HBI"),
        "cmp.slip_centre": ("slip", "slip per event at (0, 0), median, against HBI"),
        "cmp.mw_later": ("mw", "Mw of the events after the first, median, against HBI")})
    wall, loop, operator = hbi.rsfcycle_times(ours)
    hbi_wall, hbi_cpu = hbi.hbi_time(peer)
    for key, value, unit, text in (
            ("bp4-qd.cost", wall and hbi.duration(wall), "", "1000 years, the whole run"),
            ("cost.time_loop", loop and f"{loop:.0f}", "s", "time loop, 1000 years"),
            ("cost.operator", operator and f"{operator:.0f}", "s", "operator build and its file")):
        if value:
            rows.append((key, value, unit, text))
    hbi.record(HERE, rows, *hbi.context_of(ours))
    if hbi_wall:
        hbi.record(HERE, [("cost.hbi", hbi.duration(hbi_wall), "", "HBI's whole run at 1 km "
                           f"({hbi_cpu:.0f} s CPU)")], *hbi.context_of(peer))


def main(argv=None):
    return hbi.driver(__doc__, HERE, "bp4", dict(
        runs=runs, peer=None, figures=figures, results=results), argv=argv, equal=EQUAL)


if __name__ == "__main__":
    sys.exit(main())
