#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""SEAS BP7-QD: rsfcycle against HBI at 10 m over 10 years (and HBI at
5 m over the first two events); the figures and results.csv of
benchmarks/seas-bp7/README.md.

From the repository's root, with the package on the path:

  PYTHONPATH=python /usr/bin/python3 benchmarks/seas-bp7/run.py COMMAND ...

  runs     prm/seas-bp7-qd.prm into WORK/rsfcycle-10m on 2 ranks: the
           operator about 2.5 min, the 10 years about 8 min
  peer     HBI with BP7's nucleation (HBI_SRC or --hbi-src) into
           WORK/hbi-10m, about 9 min on one core; also
           --cell 5 --tend 2.65e7 (WORK/hbi-5m, the first two events) and
           --eps 1e-8 --name hbi-10m-eps8 (the first event's onset)
  figures  figures/*.png from WORK/hbi-10m and WORK/rsfcycle-10m
  results  the event catalogues and their differences into results.csv
           (rsfcycle.results.record)

WORK is --work (default benchmarks/seas-bp7/runs). An event is max V >=
1 mm/s in global.dat (rsfcycle.catalog.detect, runs within 100 s
joined); years of 365.25 days; the slip is the centre station
fltst_strk+000dp+000's; "later" means the events after the first.
"""

import os
import sys

from rsfcycle.peers import hbi

HERE = os.path.dirname(os.path.abspath(__file__))
STATION = "fltst_strk+000dp+000"
# `equal`: the shipped file, its step tolerance, the station, the merge [s]
EQUAL = ("prm/seas-bp7-qd.prm", "1e-5", STATION, 100.0)
NAMES = ("rsfcycle-10m", "hbi-10m", "hbi-5m", "hbi-10m-eps8")
# results.csv's rows against HBI at 10 m: key, figure (hbi.FIGURES), text
COMPARED = """
bp7-qd.peak_slip_rate peak later events' peak slip rate against HBI at 10 m
cmp.first_peak first_peak first event's peak slip rate
cmp.first_mw first_mw first event's Mw
cmp.first_slip first_slip first event's slip at the centre
cmp.second_event second second event
cmp.later_slip slip later events' slip at the centre
cmp.later_mw mw later events' Mw
"""


def runs(args):
    """rsfcycle's run into --work (about 10 min on 2 ranks)."""
    hbi.run_rsfcycle("prm/seas-bp7-qd.prm", os.path.join(args.work, "rsfcycle-10m"),
                     {}, args.ranks, args.binary)


def present(work, required=("rsfcycle-10m", "hbi-10m")):
    """{name: folder} of NAMES in WORK; the required ones must be there."""
    found = {n: os.path.join(work, n) for n in NAMES if os.path.isdir(os.path.join(work, n))}
    missing = [n for n in required if n not in found]
    if missing:
        raise FileNotFoundError(f"{work}: no {', '.join(missing)} (run.py runs, run.py peer)")
    return found


def figures(args):
    """figures/*.png from the run folders in --work."""
    found = present(args.work)
    hbi.plane_figures([("HBI-10m", found["hbi-10m"]), ("rsfcycle-10m", found["rsfcycle-10m"])],
                      os.path.join(HERE, "figures"), unit=1.0, gaps=(0.1 * hbi.YEAR, 0.1),
                      contour=0.05)


def results(args):
    """results.csv from the run folders in --work."""
    found = present(args.work)
    cat = {n: hbi.catalogue(f, STATION, merge=100.0) for n, f in found.items()}
    for name, events in cat.items():
        hbi.print_catalogue(name, events, unit=1.0)
    ours, peer = cat["rsfcycle-10m"], cat["hbi-10m"]
    seq = {n: hbi.sequence(c) for n, c in cat.items()}
    d = hbi.differences(ours, peer)
    yr = hbi.YEAR

    def rel(x):
        return hbi.signed(100 * x, 1)
    fine = "hbi-5m" in cat
    own = rel(seq["hbi-5m"]["second"] / seq["hbi-10m"]["second"] - 1) if fine else None
    rows = [
        ("bp7-qd.events", f"{len(ours)} in 10 yr", "", f"events (max V ≥ 1 mm/s); HBI: {len(peer)}"),
        ("bp7-qd.recurrence", rel(d["interval"]) + " %" + (f" (HBI's 10 → 5 m: {own} %)" if fine
                                                           else ""), "",
         "mean interval after the first event against HBI at 10 m, "
         f"{seq['rsfcycle-10m']['interval'] / yr:.4f} against {seq['hbi-10m']['interval'] / yr:.4f} yr"),
    ]
    rows += hbi.compare_rows(ours, peer, COMPARED)
    onset = cat.get("hbi-10m-eps8", peer)
    rows.append(("cmp.first_onset", rel(ours[0]["start"] / onset[0]["start"] - 1), "%",
                 f"first event's onset, {ours[0]['start']:.3f} s against HBI's "
                 f"{onset[0]['start']:.3f} s" + (" at tolerance 1e-8" if onset is not peer else "")))
    if fine and len(cat["hbi-5m"]) > 1 and len(ours) > 1:
        d5 = hbi.differences(ours, cat["hbi-5m"])
        rows += [("cmp.second_event_5m", rel(d5["second"]), "%", "second event against HBI 5 m "
                  f"({seq['hbi-5m']['second'] / yr:.4f} yr)"),
                 ("cmp.second_peak_5m", rel(ours[1]["peak"] / cat["hbi-5m"][1]["peak"] - 1), "%",
                  f"second event's peak slip rate against HBI 5 m, {ours[1]['peak']:.4f} against "
                  f"{cat['hbi-5m'][1]['peak']:.4f} m/s")]
    wall, loop, operator = hbi.rsfcycle_times(found["rsfcycle-10m"])
    hbi_wall, hbi_cpu = hbi.hbi_time(found["hbi-10m"])
    costs = [("bp7-qd.cost", wall, lambda w: (hbi.duration(w), ""), "10 years, the whole run"),
             ("cost.time_loop", loop, lambda s: (f"{s:.0f}", "s"), "time loop, 10 years"),
             ("cost.operator", operator, lambda s: (f"{s:.0f}", "s"), "operator build")]
    rows += [(key, *fmt(v), text) for key, v, fmt, text in costs if v]
    hbi.record(HERE, rows, *hbi.context_of(found["rsfcycle-10m"]))
    if hbi_wall:
        hbi.record(HERE, [("cost.hbi", hbi.duration(hbi_wall), "", "HBI's whole run at 10 m "
                           f"({hbi_cpu:.0f} s CPU)")], *hbi.context_of(found["hbi-10m"]))


def main(argv=None):
    return hbi.driver(__doc__, HERE, "bp7", dict(
        runs=runs, peer=None, figures=figures, results=results), argv=argv, equal=EQUAL)


if __name__ == "__main__":
    sys.exit(main())
