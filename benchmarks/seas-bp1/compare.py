#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Compare SEAS BP1-QD runs of rsfcycle with a peer run (QDYN).

Usage:
  compare.py --rsfcycle LABEL=RUNDIR [...] [--qdyn LABEL=SERIES.csv [...]]
             [--out DIR]

RUNDIR: an rsfcycle run folder with the SEAS files (prm/seas-bp1-qd.prm
writes them): global.dat (t, log10 max V) and fltst_dp000 (t, surface
slip). SERIES.csv: the peer's time series with the columns t_s (or t_yr in
QDYN's 365-day years), max_slip_rate [m/s] and surface_slip [m].

Both are reduced alike: an event is where the maximum slip rate exceeds
1 mm/s (the SEAS threshold), from the first sample above to the first
below; per event the start time, the peak slip rate and the coseismic
surface slip (the surface slip at the end minus at the start). Printed:
first-event time, mean recurrence interval (of the events after the
first `--skip` ones), median peak slip rate and surface slip, each with
its difference from the first peer run (or from the first run given), and
the first `--events` events one by one against that run's.
Writes DIR/max-slip-rate.png (log10 max V over time),
DIR/surface-slip.png (surface slip over time) and DIR/recurrence.png
(every interval at its event's start, and its difference in % from the
first run's interval of the same number; the band is ±0.5 %).
"""
import argparse
import os

import numpy as np
from seas_files import YEAR, read_table

QDYN_YEAR = 365.0 * 24 * 3600  # QDYN's (constants.f90)
THRESHOLD = 1e-3  # [m/s]


def rsfcycle_series(rundir):
    g = read_table(os.path.join(rundir, "global.dat"))
    s = read_table(os.path.join(rundir, "fltst_dp000"))
    n = min(len(g), len(s))
    return g[:n, 0], 10 ** g[:n, 1], s[:n, 1]


def peer_series(path):
    import csv

    with open(path) as f:
        reader = csv.DictReader(f)
        rows = list(reader)
    if "t_s" in rows[0]:
        t = np.array([float(r["t_s"]) for r in rows])
    else:
        t = np.array([float(r["t_yr"]) for r in rows]) * QDYN_YEAR
    v = np.array([float(r["max_slip_rate"]) for r in rows])
    slip = np.array([float(r["surface_slip"]) for r in rows])
    return t, v, slip


def events(t, v, slip, merge=0.0):
    """(start [s], peak [m/s], surface slip [m]) of every completed event;
    a crossing that starts within `merge` seconds of the end of the one
    before is part of it (BP1-FD's slip rate crosses 1 mm/s again and again
    for minutes after a rupture)."""
    above = v > THRESHOLD
    spans = []  # [first index above (or the sample before), end index]
    i = 0
    n = len(t)
    while i < n:
        if above[i]:
            j = i
            while j < n and above[j]:
                j += 1
            if j == n:
                break  # still running at the end
            if spans and t[i] - t[spans[-1][1]] <= merge:
                spans[-1][1] = j
            else:
                spans.append([i, j])
            i = j
        else:
            i += 1
    result = []
    for i, j in spans:
        start = i - 1 if i > 0 else i
        result.append((t[i], v[i:j].max(), slip[j] - slip[start]))
    return np.array(result)


def summary(label, ev, t_end, skip):
    first = ev[0, 0] / YEAR
    recurrence = np.diff(ev[:, 0])[skip:] / YEAR if len(ev) > skip + 1 else []
    return {
        "label": label,
        "events": len(ev),
        "end": t_end / YEAR,
        "first": first,
        "recurrence": np.mean(recurrence) if len(recurrence) else np.nan,
        "recurrence_spread": (np.ptp(recurrence) if len(recurrence) else np.nan),
        "peak": np.median(ev[skip:, 1]) if len(ev) > skip else ev[0, 1],
        "slip": np.median(ev[skip:, 2]) if len(ev) > skip else ev[0, 2],
        "first_peak": ev[0, 1],
        "first_slip": ev[0, 2],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rsfcycle", action="append", default=[])
    parser.add_argument("--qdyn", action="append", default=[])
    parser.add_argument("--skip", type=int, default=2,
                        help="events left out of the means (spin-up)")
    parser.add_argument("--events", type=int, default=6,
                        help="events compared one by one")
    parser.add_argument("--tmax", type=float, default=None,
                        help="the figures' time axis ends here [yr]")
    parser.add_argument("--merge", type=float, default=0.0,
                        help="crossings of 1 mm/s within this many seconds "
                        "of the one before are one event [s]")
    parser.add_argument("--out", default=".")
    args = parser.parse_args()

    runs = []
    for item in args.qdyn:
        label, path = item.split("=", 1)
        runs.append((label, *peer_series(path)))
    for item in args.rsfcycle:
        label, path = item.split("=", 1)
        runs.append((label, *rsfcycle_series(path)))

    rows = [summary(r[0], events(*r[1:], args.merge), r[1][-1], args.skip) for r in runs]
    ref = rows[0]
    print("| run | simulated [yr] | events | first event [yr] | mean recurrence "
          "[yr] (spread) | first: peak V [m/s], surface slip [m] | median "
          "peak V [m/s] | median surface slip [m] |")
    print("|---|---|---|---|---|---|---|---|")

    def diff(x, y):
        if x is y or y is None or x == y:
            return ""
        return " (%+.2f %%)" % (100 * (x / y - 1))

    for r in rows:
        print("| %s | %.0f | %d | %.2f%s | %.2f (%.2f)%s | %.2f, %.3f | %.2f%s "
              "| %.3f%s |" % (
                  r["label"], r["end"], r["events"], r["first"],
                  diff(r["first"], ref["first"]), r["recurrence"],
                  r["recurrence_spread"],
                  diff(r["recurrence"], ref["recurrence"]), r["first_peak"],
                  r["first_slip"], r["peak"], diff(r["peak"], ref["peak"]),
                  r["slip"], diff(r["slip"], ref["slip"])))

    # event by event against the reference (the first run given)
    ref_events = events(*runs[0][1:], args.merge)
    print()
    print("| run | event | start [yr] | interval [yr] | peak V [m/s] | "
          "surface slip [m] |")
    print("|---|---|---|---|---|---|")
    for r in runs:
        ev = events(*r[1:], args.merge)
        for k in range(min(len(ev), len(ref_events), args.events)):
            interval = (ev[k, 0] - ev[k - 1, 0]) / YEAR if k > 0 else None
            ref_interval = ((ref_events[k, 0] - ref_events[k - 1, 0]) / YEAR
                            if k > 0 else None)
            print("| %s | %d | %.3f%s | %s | %.3f%s | %.4f%s |" % (
                r[0], k + 1, ev[k, 0] / YEAR,
                diff(ev[k, 0], ref_events[k, 0]),
                "-" if interval is None else "%.3f%s" % (
                    interval, diff(interval, ref_interval)),
                ev[k, 1], diff(ev[k, 1], ref_events[k, 1]), ev[k, 2],
                diff(ev[k, 2], ref_events[k, 2])))

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    os.makedirs(args.out, exist_ok=True)
    for name, column, ylabel in (
            ("max-slip-rate.png", 2, "log10 max slip rate [m/s]"),
            ("surface-slip.png", 3, "surface slip [m]")):
        fig, ax = plt.subplots(figsize=(9, 4))
        for r in runs:
            y = np.log10(r[column]) if column == 2 else r[column]
            ax.plot(r[1] / YEAR, y, lw=0.8, label=r[0])
        ax.set_xlabel("time [yr]")
        if args.tmax:
            ax.set_xlim(0, args.tmax)
        ax.set_ylabel(ylabel)
        ax.legend()
        fig.tight_layout()
        fig.savefig(os.path.join(args.out, name), dpi=120)
        plt.close(fig)

    # the recurrence: every interval at its event's start, and its
    # difference from the reference's interval of the same number
    fig, (ax, ax_diff) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    ref_interval = np.diff(ref_events[:, 0]) / YEAR
    for r in runs:
        ev = events(*r[1:], args.merge)
        interval = np.diff(ev[:, 0]) / YEAR
        line, = ax.plot(ev[1:, 0] / YEAR, interval, "o-", ms=3, lw=0.8,
                        label=r[0])
        n = min(len(interval), len(ref_interval))
        if r is not runs[0] and n > 0:
            ax_diff.plot(ev[1:n + 1, 0] / YEAR,
                         100 * (interval[:n] / ref_interval[:n] - 1), "o-",
                         ms=3, lw=0.8, color=line.get_color())
    ax.set_ylabel("interval to the event before [yr]")
    ax.legend()
    ax_diff.axhspan(-0.5, 0.5, color="0.9")
    ax_diff.axhline(0, color="0.5", lw=0.5)
    ax_diff.set_ylabel("against %s [%%]" % runs[0][0])
    ax_diff.set_xlabel("event start [yr]")
    if args.tmax:
        ax_diff.set_xlim(0, args.tmax)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "recurrence.png"), dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main()
