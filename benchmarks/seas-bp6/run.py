#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""SEAS BP6-QD-A and BP6-QD-S: rsfcycle against HBI (fluid injection into
a velocity-strengthening fault); the figures and results.csv of
benchmarks/seas-bp6/README.md.

From the repository's root, with the package on the path:

  PYTHONPATH=python /usr/bin/python3 benchmarks/seas-bp6/run.py COMMAND ...

  runs     prm/seas-bp6-qd-a.prm and -s.prm into WORK/rsfcycle-a and
           WORK/rsfcycle-s on one rank (about 10 s and 1 min)
  peer     HBI with the closed-form pore pressure (HBI_SRC or --hbi-src)
           into WORK/hbi-a and WORK/hbi-s (--law A or S for one), at
           10 m about 3 and 6 min on one core
  figures  figures/bp6-qd-a.png and bp6-qd-s.png from those folders
  results  stations, slip fronts and maximum slip rates of both codes and
           their differences into results.csv (rsfcycle.results.record)
  equal    the cost at equal accuracy: rsfcycle at its shipped step
           tolerance and 3 and 10 times looser (one rank), HBI at eps_r
           1e-6, 1e-5, 1e-4 (one core), side by side with --run into
           WORK/equal, per law; each code's cheapest run whose slip fronts,
           slips and peak slip rate are unchanged (within 0.01 %,
           rsfcycle.equal), the ratio of the costs into results.csv

WORK is --work (default benchmarks/seas-bp6/runs). Days of 86400 s, a
year of 365.25 days; the slip front is the largest |x3| where the slip
reaches 1 mm (linear between profile positions and between profile rows).
"""

import os
import sys

import numpy as np

from rsfcycle import catalog, seas, seas_rules
from rsfcycle.equal import unchanged_values
from rsfcycle.peers import hbi

HERE = os.path.dirname(os.path.abspath(__file__))
DAY = 86400.0
SLIP_DAYS = [30, 100, 365.25, 730.5]
FRONT_DAYS = [100, 365, 730]
PLOTTED = ["fltst_strk+00", "fltst_strk+10", "fltst_strk+25", "fltst_strk+50"]
PROFILE_DAYS = [30, 100, 365, 730]
THRESHOLD = 1e-3  # m: the slip front
LAWS = {"A": "ageing law", "S": "slip law"}


def runs(args):
    """rsfcycle's runs into --work (about 1 min on one core)."""
    for law in args.laws:
        hbi.run_rsfcycle(f"prm/seas-bp6-qd-{law.lower()}.prm",
                         os.path.join(args.work, "rsfcycle-" + law.lower()), {}, args.ranks,
                         args.binary)


def peer(args):
    """HBI for each law into --work (10 m: about 9 min on one core)."""
    name = args.name
    for law in [args.law] if args.law else ["A", "S"]:
        args.law = law
        args.name = name or "hbi-" + law.lower() + ("-" + hbi.label(args.cell) if args.cell else "")
        hbi.peer("bp6", args)


def front(x, slip):
    """The largest |x| where slip >= THRESHOLD (linear between points)."""
    best = 0.0
    for end in (0, -1):
        if slip[end] >= THRESHOLD:
            best = max(best, abs(x[end]))
    for i in range(len(x) - 1):
        for a, b in ((i, i + 1), (i + 1, i)):
            if slip[a] >= THRESHOLD > slip[b]:
                best = max(best, abs(x[a] + (THRESHOLD - slip[a]) / (slip[b] - slip[a])
                                     * (x[b] - x[a])))
    return best


def summary(folder):
    """Per station: slips at SLIP_DAYS [m], (peak slip rate [m/s], its
    day); the fault's (max slip rate, day); the fronts at FRONT_DAYS [m]."""
    stations = {}
    for name in seas_rules.BP6_STATIONS:
        t, slip = hbi.column(folder, name, "slip")
        _, lv = hbi.column(folder, name, "slip_rate")
        k = int(np.argmax(lv))
        stations[name] = dict(slip=[float(np.interp(d * DAY, t, slip)) for d in SLIP_DAYS],
                              peak=(10 ** lv[k], t[k] / DAY))
    _, g = seas.table(hbi.seas_path(folder, "global.dat"))
    k = int(np.argmax(g[:, 1]))
    x, t, _, values = seas.profile(hbi.seas_path(folder, "slip.dat"))
    fronts = [front(x, [np.interp(d * DAY, t, values[:, j]) for j in range(len(x))])
              for d in FRONT_DAYS]
    return dict(stations=stations, peak=(10 ** g[k, 1], g[k, 0] / DAY), fronts=fronts,
                events=len(catalog.detect(g[:, 0], 10 ** g[:, 1])))


def pair(work, law):
    """rsfcycle's and HBI's run folders of a law."""
    folders = [os.path.join(work, f"{code}-{law}") for code in ("rsfcycle", "hbi")]
    for folder in folders:
        if not os.path.isdir(folder):
            raise FileNotFoundError(f"{folder}: no run folder (run.py runs, run.py peer)")
    return folders


def figures(args):
    """figures/bp6-qd-*.png from the run folders in --work."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for law in args.laws:
        fig, axes = plt.subplots(2, 2, figsize=(11, 8))
        for style, (label, folder) in zip(("-", "--"), zip(("rsfcycle", "HBI"),
                                                           pair(args.work, law.lower()))):
            for c, name in enumerate(PLOTTED):
                t, slip = hbi.column(folder, name, "slip")
                _, lv = hbi.column(folder, name, "slip_rate")
                where = f"x3 = {int(name[-3:]) / 10:g} km" if style == "-" else None
                axes[0, 0].plot(t / DAY, 10 ** lv, style, color=colours[c], label=where)
                axes[0, 1].plot(t / DAY, slip, style, color=colours[c])
            x, t, _, values = seas.profile(hbi.seas_path(folder, "slip.dat"))
            for c, day in enumerate(PROFILE_DAYS):
                axes[1, 0].plot(x / 1e3, [np.interp(day * DAY, t, values[:, j])
                                          for j in range(len(x))], style, color=colours[c],
                                label=f"{day} days" if style == "-" else None)
            _, g = seas.table(hbi.seas_path(folder, "global.dat"))
            axes[1, 1].plot(g[:, 0] / DAY, 10 ** g[:, 1], style, color="k", label=label)
        axes[0, 0].set(yscale="log", xlabel="t [days]", ylabel="slip rate [m/s]",
                       ylim=(1e-12, None))
        axes[0, 1].set(xlabel="t [days]", ylabel="slip [m]")
        axes[1, 0].set(xlabel="x3 [km]", ylabel="slip [m]")
        axes[1, 1].set(yscale="log", xlabel="t [days]", ylabel="max slip rate [m/s]")
        for ax in (axes[0, 0], axes[1, 0], axes[1, 1]):
            ax.legend(fontsize=8)
        fig.suptitle(f"BP6-QD-{law}")
        fig.tight_layout()
        fig.savefig(os.path.join(HERE, "figures", f"bp6-qd-{law.lower()}.png"), dpi=110)
        plt.close(fig)


def spread(values):
    """'−0.14 … −0.33' style: the lowest and highest of percentages."""
    low, high = min(values), max(values)
    if f"{low:+.2f}" == f"{high:+.2f}":
        return f"{low:+.2f}"
    return f"{low:+.2f} … {high:+.2f}".replace("-", "\u2212")


def results(args):
    """results.csv from the run folders in --work."""
    for law in args.laws:
        ours, peer_folder = pair(args.work, law.lower())
        a, b = summary(ours), summary(peer_folder)
        key, what = f"bp6-qd-{law.lower()}", LAWS[law]
        fronts = [100 * (x / y - 1) for x, y in zip(a["fronts"], b["fronts"])]
        east = [n for n in seas_rules.BP6_STATIONS if not n.endswith("-15")]
        slips = [100 * (a["stations"][n]["slip"][3] / b["stations"][n]["slip"][3] - 1)
                 for n in east]
        peaks = [100 * (a["stations"][n]["peak"][0] / b["stations"][n]["peak"][0] - 1)
                 for n in east]
        centre = a["stations"]["fltst_strk+00"]["slip"][3], b["stations"]["fltst_strk+00"]["slip"][3]
        print(f"BP6-QD-{law}: fronts [km] at {FRONT_DAYS} days: rsfcycle "
              f"{[round(f / 1e3, 3) for f in a['fronts']]}, HBI {[round(f / 1e3, 3) for f in b['fronts']]}")
        rows = [
            (key + ".events", "none in 2 yr (aseismic)" if not a["events"] else
             f"{a['events']} in 2 yr", "", f"{what}: events"),
            (key + ".recurrence", "no events; slip fronts " + spread(fronts) + " %", "",
             f"{what}: slip front (slip ≥ 1 mm) at 100 d, 1 yr, 2 yr, "
             + " / ".join(f"{f / 1e3:.3f}" for f in a["fronts"]) + " against "
             + " / ".join(f"{f / 1e3:.3f}" for f in b["fronts"]) + " km"),
            (key + ".peak_slip_rate", f"{100 * (a['peak'][0] / b['peak'][0] - 1):+.1f}", "%",
             f"{what}: the fault's maximum slip rate, {a['peak'][0]:.4g} m/s at day "
             f"{a['peak'][1]:.1f} against {b['peak'][0]:.4g} at {b['peak'][1]:.1f}"),
            (f"{law.lower()}.slip_stations", spread(slips), "%",
             f"{what}: slip after two years at the stations 0 … 7.5 km"),
            (f"{law.lower()}.slip_centre", f"{100 * (centre[0] / centre[1] - 1):+.2f}", "%",
             f"{what}: slip at x3 = 0 after two years, {1e3 * centre[0]:.2f} against "
             f"{1e3 * centre[1]:.2f} mm"),
            (f"{law.lower()}.peak_stations", spread(peaks), "%",
             f"{what}: peak slip rate at the stations"),
        ]
        wall, _, _ = hbi.rsfcycle_times(ours)
        if wall:
            rows.append((key + ".cost", f"{wall:.2g}", "s", f"{what}: two years, operator included"))
        hbi.record(HERE, rows, *hbi.context_of(ours))
        _, cpu = hbi.hbi_time(peer_folder)
        if cpu:
            hbi.record(HERE, [(f"cost.hbi_{law.lower()}", f"{cpu:.0f}", "s",
                               f"HBI {what}, CPU time")], *hbi.context_of(peer_folder))


def compared(folder):
    """What `equal` keeps unchanged: the slip fronts, the slips after two
    years at the stations 0 … 7.5 km and the fault's peak slip rate."""
    s = summary(folder)
    east = [n for n in seas_rules.BP6_STATIONS if not n.endswith("-15")]
    return s["fronts"] + [s["stations"][n]["slip"][3] for n in east] + [s["peak"][0]]


def equal(args):
    """The cost at equal accuracy against HBI (each code's cheapest run with unchanged results)."""
    for law in args.laws:
        hbi.equal_command(args, HERE, "bp6", f"prm/seas-bp6-qd-{law.lower()}.prm", "1e-6",
                          compared, label=law.lower(), hbi_options=dict(law=law),
                          text=LAWS[law], compare=unchanged_values)


def laws(p):
    p.add_argument("--laws", nargs="+", choices=["A", "S"], default=["A", "S"])


def ranks(p):
    laws(p)
    p.set_defaults(ranks=1)


def main(argv=None):
    return hbi.driver(__doc__, HERE, "bp6", dict(
        runs=runs, peer=peer, figures=figures, results=results, equal=equal),
        dict(runs=ranks, figures=laws, results=laws, equal=laws), argv=argv)


if __name__ == "__main__":
    sys.exit(main())
