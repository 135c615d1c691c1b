#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Compare SEAS BP5-QD runs: rsfcycle's run folders and the peer's SEAS files.

Usage:
  compare_bp5.py --run LABEL=DIR [--run LABEL=DIR ...] [--out FIGDIR]
                 [--merge SECONDS] [--station NAME] [--gaps S1,S2]
                 [--contour SECONDS] [--unit km|m]

BP7 (benchmarks/seas-bp7/README.md): --station fltst_strk+000dp+000
--gaps 3.15576e6,0.1 --contour 0.05 --unit m (the hypocentres and the
contours in m; the peer's events.dat must give them in that unit).

DIR holds a run's SEAS files (rsfcycle writes them without a suffix, the
HBI converter peer/hbi2seas.py with .dat): global.dat (t, log10 max V,
moment rate), the station --station (default fltst_strk+00dp+00, BP5's
surface slip at x2 = 0), and, if
present, rupture.dat (x2 x3 t; rsfcycle) or events.dat (HBI's hypocentres)
and the profiles slip_2_depth.dat, slip_2_strike.dat.

An event: the maximum slip rate at or above 1 mm/s (the SEAS threshold),
from the first sample above to the first below; crossings closer than
--merge seconds to the previous event's end belong to it. Per event: the
start, the peak slip rate, the duration, the moment (the trapezoidal
integral of the moment rate), the coseismic surface slip at x2 = 0, the
hypocentre (rsfcycle: the first node of rupture.dat in the event; HBI:
events.dat). Printed: every event of every run, and the differences of
the first event's time, the mean recurrence interval (of the events after
the first), the median peak slip rate and surface slip from the first run
given (the reference).
Writes FIGDIR/max-slip-rate.png, FIGDIR/slip-depth.png,
FIGDIR/slip-strike.png (cumulative slip every --gaps S1 seconds between
events, every S2 in them; default 10 years and 5 s) and
FIGDIR/rupture-LABEL.png (rupture-time contours, every --contour seconds
(default 2), of the first two events from rupture.dat).
"""
import argparse
import os

import numpy as np

YEAR = 365.25 * 24 * 3600
THRESHOLD = -3.0  # log10 m/s


def path(d, name):
    for candidate in (name, name + ".dat"):
        p = os.path.join(d, candidate)
        if os.path.exists(p):
            return p
    return None


def read(p):
    rows = []
    with open(p) as f:
        for line in f:
            s = line.strip()
            if not s or s[0] == "#" or s[0].isalpha():
                continue
            rows.append([float(x) for x in s.split()])
    return np.array(rows)


def detect(t, logv, merge):
    above = logv >= THRESHOLD
    spans = []
    i = 0
    n = len(t)
    while i < n:
        if above[i]:
            j = i
            while j < n and above[j]:
                j += 1
            if spans and t[i] - spans[-1][1] < merge:
                spans[-1] = (spans[-1][0], t[min(j, n - 1)], spans[-1][2], j)
            else:
                spans.append((t[i], t[min(j, n - 1)], i, j))
            i = j
        else:
            i += 1
    return [s for s in spans if s[3] < n]  # completed events only


def catalogue(d, merge, station, scale):
    g = read(path(d, "global.dat"))
    t, logv, mrate = g[:, 0], g[:, 1], g[:, 2]
    surf = read(path(d, station))
    rupture = path(d, "rupture.dat")
    rupture = read(rupture) if rupture else None
    hbi = path(d, "events.dat")
    hbi = read(hbi) if hbi else None
    events = []
    for k, (start, end, i, j) in enumerate(detect(t, logv, merge)):
        sel = slice(i, j + 1)
        moment = np.trapz(mrate[sel], t[sel])
        s0 = np.interp(start, surf[:, 0], surf[:, 1])
        s1 = np.interp(end, surf[:, 0], surf[:, 1])
        hypo = (np.nan, np.nan)
        if rupture is not None and len(rupture):
            inside = rupture[(rupture[:, 2] >= start - 1) & (rupture[:, 2] <= end)]
            if len(inside):
                first = inside[np.argmin(inside[:, 2])]
                hypo = (first[0] / scale, first[1] / scale)
        elif hbi is not None and k < len(hbi):
            hypo = (hbi[k, 5], hbi[k, 6])
        events.append(
            dict(start=start, end=end, peak=10 ** logv[sel].max(),
                 moment=moment, slip=s1 - s0, hypo=hypo))
    return events, (t, logv)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--run", action="append", required=True)
    ap.add_argument("--out", default=None)
    ap.add_argument("--merge", type=float, default=3600.0)
    ap.add_argument("--station", default="fltst_strk+00dp+00")
    ap.add_argument("--gaps", default=f"{10 * YEAR},5")
    ap.add_argument("--contour", type=float, default=2.0)
    ap.add_argument("--unit", choices=("km", "m"), default="km")
    a = ap.parse_args()
    scale = 1e3 if a.unit == "km" else 1.0
    gap_between, gap_in = (float(x) for x in a.gaps.split(","))
    runs = []
    for item in a.run:
        label, d = item.split("=", 1)
        ev, series = catalogue(d, a.merge, a.station, scale)
        runs.append((label, d, ev, series))
    for label, d, ev, _ in runs:
        print(f"== {label} ({d}): {len(ev)} events")
        print(f"   #   start [yr]  peak [m/s]  duration [s]  Mw     slip at {a.station} [m]  hypocentre x2, x3 [{a.unit}]")
        for k, e in enumerate(ev):
            mw = 2 / 3 * (np.log10(max(e["moment"], 1)) - 9.1)
            print(f"  {k + 1:2d} {e['start'] / YEAR:11.3f} {e['peak']:11.4f} "
                  f"{e['end'] - e['start']:12.1f}  {mw:5.3f} {e['slip']:12.4f}"
                  f"      {e['hypo'][0]:7.2f} {e['hypo'][1]:6.2f}")
    ref_label, _, ref, _ = runs[0]

    def summary(ev):
        starts = np.array([e["start"] for e in ev])
        return dict(
            first=starts[0] if len(starts) else np.nan,
            second=starts[1] if len(starts) > 1 else np.nan,
            interval=np.diff(starts[1:]).mean() if len(starts) > 2 else np.nan,
            peak=np.median([e["peak"] for e in ev[1:]]) if len(ev) > 1 else np.nan,
            slip=np.median([e["slip"] for e in ev[1:]]) if len(ev) > 1 else np.nan,
            mw=np.median([2 / 3 * (np.log10(e["moment"]) - 9.1) for e in ev[1:]])
            if len(ev) > 1 else np.nan)
    r = summary(ref)
    print(f"== against {ref_label} (events after the first: intervals, "
          "medians)")
    for label, _, ev, _ in runs[1:]:
        s = summary(ev)
        for key, unit, per in (("second", "yr", YEAR), ("interval", "yr", YEAR),
                               ("peak", "m/s", 1), ("slip", "m", 1)):
            print(f"  {label:12s} {key:9s} {s[key] / per:10.4f} {unit:4s} "
                  f"vs {r[key] / per:10.4f}: {100 * (s[key] / r[key] - 1):+7.2f} %")
        print(f"  {label:12s} Mw        {s['mw']:10.4f}      vs {r['mw']:10.4f}: "
              f"{s['mw'] - r['mw']:+.4f}")
    if not a.out:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(a.out, exist_ok=True)
    fig, ax = plt.subplots(figsize=(9, 3.5))
    for label, _, _, (t, logv) in runs:
        ax.plot(t / YEAR, logv, label=label, lw=0.8)
    ax.set_xlabel("t [yr]")
    ax.set_ylabel("log10 max slip rate [m/s]")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "max-slip-rate.png"), dpi=120)
    for line, xlabel in (("depth", f"depth x3 [{a.unit}]"), ("strike", f"x2 [{a.unit}]")):
        fig, axes = plt.subplots(1, len(runs), figsize=(5 * len(runs), 4),
                                 squeeze=False)
        for ax, (label, d, ev, _) in zip(axes[0], runs):
            p = path(d, "slip_2_" + line)
            if p is None:
                continue
            data = read(p)
            x, rows = data[0, 2:] / scale, data[1:]
            last = -1e300
            for r_ in rows:
                seismic = r_[1] >= THRESHOLD
                gap = gap_in if seismic else gap_between
                if r_[0] - last >= gap:
                    if line == "depth":
                        ax.plot(r_[2:], x, color="r" if seismic else "b", lw=0.4)
                    else:
                        ax.plot(x, r_[2:], color="r" if seismic else "b", lw=0.4)
                    last = r_[0]
            ax.set_title(label)
            if line == "depth":
                ax.invert_yaxis()
                ax.set_xlabel("slip_2 [m]")
                ax.set_ylabel(xlabel)
            else:
                ax.set_xlabel(xlabel)
                ax.set_ylabel("slip_2 [m]")
        fig.tight_layout()
        fig.savefig(os.path.join(a.out, f"slip-{line}.png"), dpi=120)
    for label, d, ev, _ in runs:
        p = path(d, "rupture.dat")
        if p is None or len(ev) == 0:
            continue
        rup = read(p)
        fig, axes = plt.subplots(1, min(2, len(ev)), figsize=(12, 3.5),
                                 squeeze=False)
        for k, ax in enumerate(axes[0]):
            e = ev[k]
            sel = rup[(rup[:, 2] >= e["start"] - 1) & (rup[:, 2] <= e["end"])]
            if len(sel) < 3:
                continue
            tt = sel[:, 2] - sel[:, 2].min()
            c = ax.tricontour(sel[:, 0] / scale, sel[:, 1] / scale, tt,
                              levels=np.arange(0, tt.max() + a.contour,
                                               a.contour),
                              cmap="viridis")
            fig.colorbar(c, ax=ax, label="rupture time [s]")
            ax.invert_yaxis()
            ax.set_xlabel(f"x2 [{a.unit}]")
            ax.set_ylabel(f"depth [{a.unit}]")
            ax.set_title(f"{label}: event {k + 1} at {e['start'] / YEAR:.1f} yr")
            ax.set_aspect("equal")
        fig.tight_layout()
        fig.savefig(os.path.join(a.out, f"rupture-{label}.png"), dpi=120)


if __name__ == "__main__":
    main()
